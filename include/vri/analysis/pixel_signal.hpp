#pragma once
// The scalar signal along one pixel's ray of a scene and its approximations
// (RaySignal) as the rows `vri ray` writes and the Python vri.ray returns.
#include <optional>
#include <vector>

#include "vri/analysis/ray_signal.hpp"
#include "vri/scene/scene.hpp"

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
