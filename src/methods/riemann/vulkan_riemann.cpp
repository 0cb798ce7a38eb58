#include "vulkan_riemann.hpp"
#include "riemann_push_constants.h"
#include "riemann.hpp"  // make_vulkan_riemann

#include <cstddef>
#include <cstdint>

#include "methods/march/ray_steps.hpp"  // world_step
#include "methods/fast_path.hpp"
#include "tables/zero_opacity.hpp"
#include "pixel_kernel.hpp"
#include "methods/march/ray_setup.hpp"
#include "transfer/float_transfer_function.hpp"

namespace vri::vulkan {

namespace {

const std::uint32_t kSpirv[] = {
#include "riemann.spv.inc"
};

// riemann.comp's push constants.
struct Params {
  VRI_RIEMANN_PUSH_CONSTANTS
};
static_assert(sizeof(Params) <= 128, "lavapipe's push constants");

}  // namespace

VulkanRiemann::VulkanRiemann(std::shared_ptr<const VulkanDevice> device, const Scene& scene)
    : VulkanGridRenderer(std::move(device), scene),
      h_(detail::world_step(scene.grid(), scene.method.step, "riemann")),
      tf_(device_, FloatTransferFunction(scene.transfer_function)) {
  // The CPU's classification (riemann.cpp): what it would leap over.
  const Skipping skipping(scene.grid(), ZeroOpacity(scene.transfer_function), scene.method.fast, "riemann");
  empty_.emplace(device_, scene.grid(), skipping.space());
  const Bindings b = inputs();
  kernel_.emplace(device_, kSpirv, static_cast<int>(b.list().size()) + 1, sizeof(Params), b.split_arrays());
}

Bindings VulkanRiemann::inputs() const {
  Bindings b;
  b.add(volume_.samples).add(gradients());
  b.add(&tf_.values).add(&tf_.bins).add(nullptr /* the rays */).add(&empty_->bits);
  return b;
}

Image VulkanRiemann::render(const Camera& camera, const RenderOptions& options) const {
  throw_if_cancelled(options);
  const GridVolume& volume = scene_.grid();
  const RaySetup rays = [&](PixelSpan span) {
    return riemann_block(camera, volume, h_, scene_.method.jitter, span, options.threads);
  };
  Params p{grid_params(*device_, volume, volume_.type, scene_.method.fast.termination), static_cast<float>(h_),
           tf_.params(), shading_params(shading_, 1), empty_->params};
  return run_pixels(device_, *kernel_, camera.width(), camera.height(), inputs().list(), rays,
                    p.grid, &p);
}

}  // namespace vri::vulkan

namespace vri {

std::unique_ptr<GpuSceneRenderer> make_vulkan_riemann(const Scene& scene) {
  return std::make_unique<vulkan::VulkanRiemann>(vulkan::VulkanDevice::shared(), scene);
}

}  // namespace vri
