#pragma once
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
#include <optional>
#include <vector>

#include "vri/core/ray.hpp"
#include "vri/volume/grid_volume.hpp"

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
