#pragma once
// adaptive (strategies coupled and decoupled: Campagnolo, Celes & de
// Figueiredo 2015) on a Vulkan device (src/methods/adaptive/adaptive.comp): the
// CPU's AdaptiveSimpsonIntegrator, one invocation per ray, in float. Its
// step decisions follow float error estimates, so its image is not the
// CPU's to the byte; it is held to the same error against `exact`
// (docs/GPU.md). It integrates the CPU's runs of non-empty macro cells
// (shaders/occupied_runs.glsl) and stops where the CPU does. Tolerances below 1e-5 are refused: float roundings in the
// estimates would then drive every step to hmin. The `guaranteed` strategy
// is vulkan_adaptive_guaranteed.hpp.
#include <memory>
#include <optional>
#include <string>

#include "compute_kernel.hpp"
#include "gpu_array.hpp"
#include "vulkan_grid_renderer.hpp"

namespace vri::vulkan {

// `scene`, once its adaptive parameters are valid and its tolerance is at
// least min_tolerance (the float estimates' floor); else throws vri::Error
// naming `what`. Called before the volume goes up to the device.
const Scene& checked_adaptive(const Scene& scene, double min_tolerance, const std::string& what);

class VulkanAdaptive final : public VulkanGridRenderer {
 public:
  static constexpr double kMinTolerance = 1e-5;
  VulkanAdaptive(std::shared_ptr<const VulkanDevice> device, const Scene& scene);
  Image render(const Camera& camera, const RenderOptions& options) const override;

 private:
  GpuTransferFunction tf_;
  std::optional<GpuEmptySpace> empty_;   // the macro cells the CPU leaps over
  std::optional<ComputeKernel> kernel_;  // made once the arrays are on the device
  // The kernel's inputs in binding order, the rays' slot null.
  Bindings inputs() const;
};

}  // namespace vri::vulkan
