#pragma once
// Checks every render makes around the render itself (issue 17; the CLI and
// the Python module alike): parameters that would crash or hang it, work caps
// estimated before it, images that must not be returned (NaN/Inf) and images
// worth a warning (all transparent). Messages name the CLI flag and the scene key.
#include <optional>
#include <string>

#include "vri/camera/camera.hpp"
#include "vri/image.hpp"
#include "vri/scene/scene.hpp"

namespace vri {

// The bound on what early termination dropped in an image rendered with
// threshold `termination` > 0: a ray stops only once T < termination, and its
// pixel keeps alpha = 1 - T, so every pixel that may have stopped has
// 1 - alpha < termination and lost at most its 1 - alpha (times the largest colour).
struct TerminationBound {
  long long pixels = 0;   // pixels with 1 - alpha < termination: those that may have stopped early
  double max_remaining = 0;  // the largest 1 - alpha among them
};
TerminationBound termination_bound(const Image& image, double termination);

// Most worker threads accepted (TBB crashes on absurd counts).
inline constexpr int kMaxThreads = 1024;

// --threads in [0, kMaxThreads]; vri::Error beyond.
int checked_threads(int threads);

// Steps, tolerances and sizes of the method: finite and > 0, each error
// naming the flag and the scene key.
void check_method_parameters(const MethodSpec& method);

// Samples per ray and in all, estimated from the step and the volume's
// diagonal; vri::Error saying how to raise the cap when over it.
void check_work(const Scene& scene, const Camera& camera);

// vri::Error if the image holds a NaN or an infinity (no file is written).
void refuse_non_finite(const Image& image, const std::string& what);

// When every pixel is transparent, the likely cause in one line ("the camera
// looks away from the volume ..."), for a warning; nullopt otherwise.
std::optional<std::string> transparency_cause(const Image& image, const Scene& scene, const Camera& camera);

}  // namespace vri
