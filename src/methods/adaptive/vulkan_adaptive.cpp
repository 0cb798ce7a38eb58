#include "vulkan_adaptive.hpp"
#include "adaptive_push_constants.h"
#include "vulkan_adaptive_guaranteed.hpp"

#include <cmath>
#include <cstdint>
#include <string>

#include "pixel_kernel.hpp"
#include "methods/march/ray_setup.hpp"
#include "vri/error.hpp"
#include "adaptive_params.hpp"
#include "methods/fast_path.hpp"
#include "tables/zero_opacity.hpp"
#include "transfer/float_transfer_function.hpp"

namespace vri::vulkan {

namespace {

const std::uint32_t kSpirv[] = {
#include "adaptive.spv.inc"
};

// adaptive.comp's push constants.
struct Params {
  VRI_ADAPTIVE_PUSH_CONSTANTS
};
static_assert(sizeof(Params) <= 128, "lavapipe's push constants");

}  // namespace

const Scene& checked_adaptive(const Scene& scene, double min_tolerance, const std::string& what) {
  const MethodSpec& m = scene.method;
  const AdaptiveParams params{m.tolerance, m.h0, m.hmin, m.hmax, parse_adaptive_strategy(m.strategy)};
  params.validate();
  if (params.tolerance < min_tolerance)  // (the minima are powers of ten: "1e-5")
    throw Error("--backend vulkan: " + what + " computes in float on the GPU; its tolerance must be at least 1e" +
                std::to_string(std::lround(std::log10(min_tolerance))) + ", got " + std::to_string(params.tolerance));
  return scene;
}

VulkanAdaptive::VulkanAdaptive(std::shared_ptr<const VulkanDevice> device, const Scene& scene)
    : VulkanGridRenderer(std::move(device), checked_adaptive(scene, kMinTolerance, "adaptive")),
      tf_(device_, FloatTransferFunction(scene.transfer_function)) {
  const MethodSpec& m = scene.method;
  // The CPU's classification (adaptive_simpson.cpp): its runs of non-empty macro cells.
  const Skipping skipping(scene.grid(), ZeroOpacity(scene.transfer_function), m.fast, "adaptive");
  empty_.emplace(device_, scene.grid(), skipping.space());
  const Bindings b = inputs();
  kernel_.emplace(device_, kSpirv, static_cast<int>(b.list().size()) + 1, sizeof(Params), b.split_arrays());
}

Bindings VulkanAdaptive::inputs() const {
  Bindings b;
  b.add(volume_.samples).add(gradients());
  b.add(&tf_.values).add(&tf_.bins).add(nullptr /* the rays */).add(&empty_->bits);
  return b;
}

Image VulkanAdaptive::render(const Camera& camera, const RenderOptions& options) const {
  throw_if_cancelled(options);
  const GridVolume& volume = scene_.grid();
  const MethodSpec& m = scene_.method;
  const double vu = volume.voxel_unit();
  const RaySetup rays = [&](PixelSpan span) { return camera_block(camera, grid_box(volume, 0), span); };
  Params p{grid_params(*device_, volume, volume_.type, 0),
           tf_.params(),
           shading_params(shading_, 1),
           static_cast<float>(m.tolerance),
           static_cast<float>(m.h0 * vu),
           static_cast<float>(m.hmin * vu),
           static_cast<float>(m.hmax * vu),
           parse_adaptive_strategy(m.strategy) == AdaptiveStrategy::Coupled ? 1 : 0,
           empty_->params};
  return run_pixels(device_, *kernel_, camera.width(), camera.height(), inputs().list(), rays,
                    p.grid, &p);
}

}  // namespace vri::vulkan

namespace vri {

std::unique_ptr<GpuSceneRenderer> make_vulkan_adaptive(const Scene& scene) {
  if (parse_adaptive_strategy(scene.method.strategy) == AdaptiveStrategy::Guaranteed)
    return std::make_unique<vulkan::VulkanGuaranteedAdaptive>(vulkan::VulkanDevice::shared(), scene);
  return std::make_unique<vulkan::VulkanAdaptive>(vulkan::VulkanDevice::shared(), scene);
}

}  // namespace vri
