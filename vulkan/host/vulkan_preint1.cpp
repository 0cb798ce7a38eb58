#include "vulkan_preint1.hpp"

#include <cstdint>

#include "integrators/float_shading.hpp"
#include "integrators/ray_steps.hpp"  // world_step
#include "vri/core/error.hpp"
#include "pixel_kernel.hpp"
#include "ray_setup.hpp"
#include "vri/tables/float_lookup.hpp"
#include "vri/tables/table_builder.hpp"

namespace vri::vulkan {

namespace {

const std::uint32_t kSpirv[] = {
#include "preint1.spv.inc"
};

// preint1.comp's push constants.
struct Params {
  GridParams grid;
  std::int32_t table_n;
  float table_lo, table_scale;
  std::int32_t lit;  // 0 unlit, 1 sampled, 2 interpolated
  float ka, kd, ks, shininess, flat;
};


}  // namespace

VulkanPreint1::VulkanPreint1(std::shared_ptr<const VulkanDevice> device, const Scene& scene)
    : VulkanGridRenderer(std::move(device), scene),
      h_(detail::world_step(scene.grid(), scene.method.step, "preint1")),
      tf_(scene.transfer_function, scene.method.table_size),
      table_(make_table_builder(scene.method.builder)->build(tf_, h_)),
      table_buffer_(device_, std::as_bytes(table_.data()), "the pre-integration table"),
      sampler_(scene.grid()),
      kernel_(device_, kSpirv, 7, sizeof(Params)) {
  const Lighting& lighting = scene.lighting;
  if (!lighting.enabled) return;
  if (lighting.mode != "sampled" && lighting.mode != "interpolated")
    throw Error("preint1: lighting mode must be sampled or interpolated, got '" + lighting.mode + "'");
  shader_.emplace(lighting, scene.grid());
  shading_.emplace(device_, lighting, *shader_, scene.grid());
  float_shading_ = std::make_unique<detail::FloatShading>(lighting, *shader_, sampler_);
  if (lighting.mode != "interpolated") return;
  weighted_.emplace(build_weighted_tables(tf_, h_));
  weighted_front_.emplace(device_, std::as_bytes(weighted_->front.data()), "the front-weighted table");
  weighted_back_.emplace(device_, std::as_bytes(weighted_->back.data()), "the back-weighted table");
}

VulkanPreint1::~VulkanPreint1() = default;

Image VulkanPreint1::render(const Camera& camera, const RenderOptions& options) const {
  throw_if_cancelled(options);
  const GridVolume& volume = scene_.grid();
  detail::FloatLighting lighting{float_shading_.get(), {}};
  if (weighted_) lighting.weighted = {weighted_->front.data().data(), weighted_->back.data().data(), nullptr};
  const std::vector<float> rays = preint1_rays(camera, volume, tf_, lighting, h_, options.threads);
  const FloatAxis axis(table_.axis());
  Params p{grid_params(volume, volume_.type, scene_.method.fast.termination), axis.size(), axis.lo(), axis.scale(),
           0, 0, 0, 0, 0, 0};
  if (shading_) {
    p.lit = weighted_ ? 2 : 1;
    p.ka = shading_->ka, p.kd = shading_->kd, p.ks = shading_->ks;
    p.shininess = shading_->shininess, p.flat = shading_->flat;
  }
  // Where a mode does not read a buffer, the volume stands in for it.
  const GpuBuffer* inputs[] = {&volume_.samples, &table_buffer_, nullptr /* the rays */,
                               shading_ ? &shading_->gradients : &volume_.samples,
                               weighted_front_ ? &*weighted_front_ : &volume_.samples,
                               weighted_back_ ? &*weighted_back_ : &volume_.samples};
  return run_pixels(device_, kernel_, camera.width(), camera.height(), inputs, rays, kPreint1RayFloats, p.grid, &p);
}

}  // namespace vri::vulkan
