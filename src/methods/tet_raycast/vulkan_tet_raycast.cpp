#include "vulkan_tet_raycast.hpp"
#include "tet_raycast_push_constants.h"
#include "tet_raycast.hpp"  // make_vulkan_tet_raycast

#include <cstdint>
#include <span>

#include "pixel_kernel.hpp"
#include "methods/march/ray_setup.hpp"
#include "vri/methods.hpp"
#include "methods/mesh_tables.hpp"
#include "mesh/point_gradients.hpp"
#include "shading/headlight_shader.hpp"
#include "tables/float_lookup.hpp"
#include "tables/preintegration_table.hpp"
#include "tables/weighted_tables.hpp"

namespace vri::vulkan {

namespace {

const std::uint32_t kSpirv[] = {
#include "tet_raycast.spv.inc"
};

// tet_raycast.comp's push constants.
struct Params {
  VRI_TET_RAYCAST_PUSH_CONSTANTS
};
static_assert(sizeof(Params) <= 128, "lavapipe's push constants");

GpuArray on_device(const std::shared_ptr<const VulkanDevice>& device, const LengthTable& t, const char* what) {
  const std::vector<float> data = t.data();
  return GpuArray(device, std::as_bytes(std::span<const float>(data)), what);
}

}  // namespace

VulkanTetRaycast::VulkanTetRaycast(std::shared_ptr<const VulkanDevice> device, const Scene& scene)
    : device_(std::move(device)),
      scene_(scene),
      mesh_(device_, scene.mesh(), scene.lighting.enabled),
      max_length_(scene.mesh().max_edge_length()),
      lengths_(scene.method.length_samples),
      mode_(!scene.lighting.enabled ? 0 : scene.lighting.mode == "interpolated" ? 2 : 1) {
  const MethodSpec& m = scene.method;
  const TetMesh& mesh = scene.mesh();
  // The tables TetRaycastIntegrator reads (make_integrator.cpp).
  if (mode_ == 2) {
    const auto w = make_weighted_length_tables(m, mesh, scene.transfer_function, scene.lighting);
    axis_ = w->front.slices().front().axis();
    tables_[0].emplace(on_device(device_, w->front, "a weighted table (lighting)"));
    tables_[1].emplace(on_device(device_, w->back, "a weighted table (lighting)"));
  } else {
    const auto slab = make_slab_table(m, mesh, scene.transfer_function);
    const LengthTable& table = dynamic_cast<const LengthTable&>(*slab);
    axis_ = table.slices().front().axis();
    tables_[0].emplace(on_device(device_, table, "the pre-integration table"));
  }
  if (mode_ != 0) {
    const Lighting& l = scene.lighting;
    const HeadlightShader checked(l, PointGradients::flat_threshold(mesh));  // refuses bad coefficients
    shading_ = {mode_,
                static_cast<float>(l.ambient),
                static_cast<float>(l.diffuse),
                static_cast<float>(l.specular),
                static_cast<float>(l.shininess),
                static_cast<float>(checked.flat_threshold())};
  }
  const Bindings b = inputs();
  kernel_.emplace(device_, kSpirv, static_cast<int>(b.list().size()) + 1, sizeof(Params), b.split_arrays());
}

Bindings VulkanTetRaycast::inputs() const {
  Bindings b;
  b.add(*tables_[0]).add(tables_[1] ? *tables_[1] : *tables_[0]);
  b.add(&mesh_.tets).add(&mesh_.neighbors).add(&mesh_.nodes).add(&mesh_.faces).add(&mesh_.lighting);
  b.add(nullptr /* the rays */);
  return b;
}

Image VulkanTetRaycast::render(const Camera& camera, const RenderOptions& options) const {
  throw_if_cancelled(options);
  const RaySetup rays = [&](PixelSpan span) { return camera_block(camera, mesh_box(scene_.mesh(), mesh_.centre), span); };
  const FloatAxis axis(axis_);
  GridParams grid{};
  grid.part_shift = device_->part_shift();
  Params p{grid,
           {axis.size(), axis.lo(), axis.scale()},
           shading_,
           static_cast<float>(max_length_),
           lengths_,
           static_cast<std::int32_t>(scene_.mesh().size()),
           mesh_.extent};
  return run_pixels(device_, *kernel_, camera.width(), camera.height(), inputs().list(), rays,
                    p.grid, &p);
}

}  // namespace vri::vulkan

namespace vri {

std::unique_ptr<GpuSceneRenderer> make_vulkan_tet_raycast(const Scene& scene) {
  return std::make_unique<vulkan::VulkanTetRaycast>(vulkan::VulkanDevice::shared(), scene);
}

}  // namespace vri
