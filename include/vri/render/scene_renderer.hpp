#pragma once
// SceneRenderer: one scene made ready to render - its parameters checked, its
// work estimated against the caps, its integrator (or, for `pt` and
// `pt-cylindrical`, its projected-tetrahedra tables) built - then rendered.
// `vri render`, the Python module and library users all render through it,
// so each gets the same checks and the same bytes for the same scene. With
// Backend::Vulkan the scene is made ready on a GPU instead (backend.hpp).
#include <memory>
#include <optional>
#include <string>

#include "vri/camera/camera.hpp"
#include "vri/integrators/error_estimating_integrator.hpp"
#include "vri/render/backend.hpp"
#include "vri/image.hpp"
#include "vri/render/renderer.hpp"
#include "vri/scene/scene.hpp"

namespace vri {

class SceneRenderer {
 public:
  // Throws vri::Error for bad parameters, work over the caps or a method the
  // volume does not support. Refers to `scene`: keep it alive and unchanged.
  // The tables are built on `threads` threads (0: every core, and a
  // Cancellation around the constructor can stop the build; with threads > 0
  // it cannot: the build runs in its own TBB arena).
  explicit SceneRenderer(const Scene& scene, Backend backend = Backend::Cpu, int threads = 0);
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  const Camera& camera() const { return camera_; }
  // The integrator's own name (with its variant), or the projected method's.
  std::string method_name() const;
  Backend backend() const { return gpu_ ? Backend::Vulkan : Backend::Cpu; }
  // "cpu", or the GPU's name ("vulkan: llvmpipe (LLVM 15.0.6, 256 bits)").
  std::string device_name() const;

  // The image; vri::Error if it holds NaN or infinity (refuse_non_finite),
  // so no caller writes one.
  Image render(const RenderOptions& options = {}) const;
  // The same scene seen through another camera (its size and work checked as
  // the scene's own): the viewer orbits and previews with the tables built once.
  Image render(const Camera& camera, const RenderOptions& options = {}) const;

  // The method as an error-estimating integrator (adaptive), or vri::Error
  // saying that `what` (a flag or function name) needs adaptive.
  const ErrorEstimatingIntegrator& error_estimating(const std::string& what) const;
  // The per-pixel error estimate of adaptive (render_error_estimate), checked as render().
  Image render_error_estimate(const RenderOptions& options = {}) const;

 private:
  void prepare(Backend backend);  // the integrator, projected tables or GPU renderer
  struct Projected;  // pt, pt-cylindrical: tables over the mesh
  const Scene& scene_;
  Camera camera_;
  std::unique_ptr<Integrator> integrator_;
  std::unique_ptr<Projected> projected_;
  std::unique_ptr<GpuSceneRenderer> gpu_;
};

}  // namespace vri
