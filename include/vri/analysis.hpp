#pragma once
// vri/analysis.hpp: what one ray or pixel sees: the signal along it and its plot.

#include <optional>
#include <vector>
#include <string>

#include "vri/geometry.hpp"
#include "vri/volume.hpp"
#include "vri/scene.hpp"

// ---- ray_signal ------------------------------------------------------------
// RaySignal: the trilinear scalar signal along one ray and its piecewise
// polynomial approximations of order 0, 1 and 2 from the same samples, with
// the error xi = int |signal - approximation| dt of each (El Hajjar et al.
// 2008, section 3.2 and Figures 1, 2, 4, 5).
//
// Samples: with a step h, t_k = t0 + k h (and t1); without one, the paper's
// "ideal" sampling: every cell-face crossing plus the midpoint of each cell
// piece, so that each second-order slab lies inside one cell.
//   order 0: a nearest-sample hold: each sample's value held up to halfway to
//            its neighbours (on uniform samples the midpoint rule of the
//            cell between two half-steps);
//   order 1: linear between consecutive samples (trapezoid rule);
//   order 2: the Lagrange parabola through samples 2j, 2j+1, 2j+2 (Simpson's
//            rule); with an odd number of intervals the last is linear.

namespace vri {

class RaySignal {
 public:
  // step: world units; nullopt for cell-face + midpoint sampling. Throws
  // vri::Error if the ray misses the volume.
  RaySignal(const GridVolume& volume, const Ray& ray, std::optional<double> step);

  const std::vector<double>& sample_t() const { return t_; }
  const std::vector<double>& sample_s() const { return s_; }
  double t0() const { return t_.front(); }
  double t1() const { return t_.back(); }

  double signal(double t) const;  // the trilinear field at ray.at(t)
  double approximation(int order, double t) const;
  // xi of order 0, 1, 2, integrated at `per_interval` midpoints per sample interval.
  double xi(int order, int per_interval = 256) const;

 private:
  const GridVolume& volume_;
  Ray ray_;
  std::vector<double> t_, s_;
  std::size_t interval(double t) const;  // k with t_k <= t <= t_{k+1}
};

}  // namespace vri

// ---- pixel_signal ----------------------------------------------------------
// The scalar signal along one pixel's ray of a scene and its approximations
// (RaySignal) as the rows `vri ray` writes and the Python vri.ray returns.

namespace vri {

// The ray through pixel (px, py) of the scene's camera, sampled every
// `step` voxel units (>= 1e-4) or, without one, at cell faces and midpoints.
// vri::Error for a pixel outside the image, a bad step or a mesh scene.
// Refers to the scene's volume: keep the scene alive.
RaySignal pixel_signal(const Scene& scene, int px, int py, std::optional<double> step);

struct RaySignalRow {
  double t, signal, order[3];
  bool is_sample;
};

// Each sample interval at `rows_per_interval` evenly spaced t (the first one
// the sample itself), then the last sample.
std::vector<RaySignalRow> signal_rows(const RaySignal& signal, int rows_per_interval = 8);

}  // namespace vri

// ---- ray_plot --------------------------------------------------------------
// An SVG figure of a RaySignal in the manner of El Hajjar et al.'s Figures 1,
// 2, 4 and 5: one panel per order, the signal in black, the approximation in
// red, their difference shaded green, the samples as dots and xi written.

namespace vri {

std::string ray_signal_svg(const RaySignal& signal);

}  // namespace vri
