#pragma once
// SceneOverrides: what a caller changes in a loaded scene before rendering it
// (the `vri render` flags, the keyword arguments of the Python vri.render).
// One place applies them, so both front ends follow the same rules.
#include <cstdint>
#include <optional>
#include <string>

#include "vri/scene/scene.hpp"

namespace vri {

struct SceneOverrides {
  std::optional<std::string> method, strategy;
  std::optional<double> step, tolerance, termination, max_samples, max_work, h0, hmin, hmax;
  std::optional<int> table_size, iterations, width, height;
  std::optional<bool> skip_empty, float_math;
  std::optional<std::uint64_t> jitter;  // riemann: the jitter's seed
  // The camera (issue 20): `fit` frames the volume's box (framing.hpp), then
  // VTK's motions in degrees and the zoom factor.
  std::optional<bool> fit;
  std::optional<double> azimuth, elevation, roll, zoom;
};

// Sets every given field; the camera's size first, then the fit, then the motions. A method other than the scene's drops the scene's
// table_size (it was chosen for the scene's own method: preint2-dual then
// keeps its default, 64) unless table_size is given too.
void apply_overrides(Scene& scene, const SceneOverrides& overrides);

// The method's part of apply_overrides, alone: what a rank of a distributed
// render applies to the scene's method to choose its ghost layer while the
// scene is still loading.
void apply_method_overrides(MethodSpec& method, const SceneOverrides& overrides);

}  // namespace vri
