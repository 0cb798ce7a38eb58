#include "vri/render.hpp"

#include <tbb/task_arena.h>

#include <optional>
#include <variant>

#include "vri/error.hpp"
#include "vri/methods.hpp"
#include "render/error_estimate.hpp"

namespace vri {

namespace {

const Scene& checked(const Scene& scene) {
  check_method_parameters(scene.method);
  return scene;
}

}  // namespace

SceneRenderer::SceneRenderer(const Scene& scene, Backend backend, int threads)
    : scene_(checked(scene)), camera_(scene.camera) {
  check_work(scene, camera_);  // before any table is built
  // The tables' builds run on as many threads as the render (--threads). Not
  // by default: work in another arena leaves the TBB group that cancels it
  // (Cancellation: the viewer's and Python's builds stay cancellable).
  if (threads <= 0) {
    prepare(backend);
    return;
  }
  tbb::task_arena arena(threads);
  arena.execute([&] { prepare(backend); });
}

void SceneRenderer::prepare(Backend backend) {
  const Scene& scene = scene_;
  const MethodSpec& m = scene.method;
  if (backend == Backend::Vulkan) {
    gpu_ = make_vulkan_scene_renderer(scene);
    return;
  }
  if (known_method(m.name).per_ray) {
    integrator_ = std::visit(
        [&](const auto& volume) { return make_integrator(m, volume, scene.transfer_function, scene.lighting); },
        scene.volume);
    return;
  }
  check_volume_kind(m, std::holds_alternative<TetMesh>(scene.volume));
  check_jitter(m);
  check_termination(m);
  if (scene.clip().active())
    throw Error("method '" + m.name + "' projects whole tetrahedra and cannot cut them at a clip plane; use " +
                method_names([](const MethodInfo& i) { return i.mesh && i.per_ray; }, "or") + " (docs/CLIPPING.md)");
  projected_ = known_method(m.name).make_projected(scene);
}

SceneRenderer::~SceneRenderer() = default;

std::string SceneRenderer::method_name() const {
  return integrator_ ? std::string(integrator_->name()) : scene_.method.name;
}

std::string SceneRenderer::device_name() const { return gpu_ ? gpu_->device_name() : "cpu"; }

Image SceneRenderer::render(const RenderOptions& options) const { return render(camera_, options); }

Image SceneRenderer::render(const Camera& camera, const RenderOptions& options) const {
  if (&camera != &camera_) check_work(scene_, camera);
  const Image image = gpu_         ? gpu_->render(camera, options)
                      : projected_ ? projected_->render(camera, options)
                                   : vri::render(camera, *integrator_, options);
  refuse_non_finite(image, "the rendered image");
  return image;
}

const ErrorEstimatingIntegrator& SceneRenderer::error_estimating(const std::string& what) const {
  if (gpu_) throw Error(what + " is not on the GPU yet: use --backend cpu");
  const auto* e = dynamic_cast<const ErrorEstimatingIntegrator*>(integrator_.get());
  if (!e) throw Error(what + " needs method 'adaptive', not '" + scene_.method.name + "'");
  return *e;
}

Image SceneRenderer::render_error_estimate(const RenderOptions& options) const {
  const Image estimate = vri::render_error_estimate(camera_, error_estimating("the error estimate"), options);
  refuse_non_finite(estimate, "the error estimate");
  return estimate;
}

}  // namespace vri
