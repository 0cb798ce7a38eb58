#include "vulkan_adaptive_guaranteed.hpp"

#include "adaptive_push_constants.h"
#include <cstdint>
#include <string>
#include <vector>

#include "pixel_kernel.hpp"
#include "methods/march/ray_setup.hpp"
#include "vulkan_adaptive.hpp"
#include "vri/error.hpp"
#include "adaptive_params.hpp"
#include "methods/fast_path.hpp"
#include "tables/zero_opacity.hpp"
#include "transfer/float_transfer_function.hpp"
#include "volume/empty_space.hpp"

namespace vri::vulkan {

namespace {

const std::uint32_t kSpirv[] = {
#include "adaptive_guaranteed.spv.inc"
};

// adaptive_guaranteed.comp's push constants.
struct Params {
  VRI_ADAPTIVE_GUARANTEED_PUSH_CONSTANTS
};
static_assert(sizeof(Params) <= 128, "lavapipe's push constants");

// The float transfer function's segments with tau not zero, as prefix counts
// (the shader's `transparent`: the same zeros the float evaluation has).
std::vector<std::int32_t> opaque_before(const FloatTransferFunction& tf) {
  std::vector<std::int32_t> before(static_cast<std::size_t>(tf.segments()) + 1, 0);
  for (int i = 0; i < tf.segments(); ++i)
    before[i + 1] = before[i] + (tf.value(3)[i] != 0 || tf.slope(3)[i] != 0 ? 1 : 0);
  return before;
}

}  // namespace

VulkanGuaranteedAdaptive::VulkanGuaranteedAdaptive(std::shared_ptr<const VulkanDevice> device, const Scene& scene)
    : VulkanGuaranteedAdaptive(std::move(device), scene, FloatTransferFunction(scene.transfer_function)) {}

VulkanGuaranteedAdaptive::VulkanGuaranteedAdaptive(std::shared_ptr<const VulkanDevice> device, const Scene& scene,
                                                   const FloatTransferFunction& tf)
    : VulkanGridRenderer(std::move(device), checked_adaptive(scene, kMinTolerance, "adaptive 'guaranteed'")),
      tf_(device_, tf),
      opaque_before_(device_, std::as_bytes(std::span<const std::int32_t>(opaque_before(tf))),
                     "the transfer function's segments") {
  const MethodSpec& m = scene.method;
  const GridVolume& volume = scene.grid();
  margin_ = static_cast<float>(interpolation_margin(volume));
  // The CPU's classification (adaptive_guaranteed.cpp): the macro cells it walks past.
  const Skipping skipping(volume, ZeroOpacity(scene.transfer_function), m.fast, "adaptive");
  empty_.emplace(device_, volume, skipping.space());
  const Bindings b = inputs();
  kernel_.emplace(device_, kSpirv, static_cast<int>(b.list().size()) + 1, sizeof(Params), b.split_arrays());
}

Bindings VulkanGuaranteedAdaptive::inputs() const {
  Bindings b;
  b.add(volume_.samples).add(gradients());
  b.add(&tf_.values).add(&tf_.bins).add(&opaque_before_).add(nullptr /* the rays */).add(&empty_->bits);
  return b;
}

Image VulkanGuaranteedAdaptive::render(const Camera& camera, const RenderOptions& options) const {
  throw_if_cancelled(options);
  const GridVolume& volume = scene_.grid();
  const MethodSpec& m = scene_.method;
  const double vu = volume.voxel_unit();
  // As the CPU's: lit, steps of at most a quarter voxel (the specular spike
  // near a vanishing gradient); a floor of 1e-4 voxel only to end the loop.
  const double hmax = shading_ ? std::min(m.hmax, 0.25) * vu : m.hmax * vu;
  const RaySetup rays = [&](PixelSpan span) { return camera_block(camera, grid_box(volume, 0), span); };
  Params p{grid_params(*device_, volume, volume_.type, 0),
           tf_.params(),
           shading_params(shading_, 1),
           static_cast<float>(m.tolerance),
           static_cast<float>(hmax),
           static_cast<float>(1e-4 * vu),
           margin_,
           empty_->params};
  return run_pixels(device_, *kernel_, camera.width(), camera.height(), inputs().list(), rays,
                    p.grid, &p);
}

}  // namespace vri::vulkan
