#pragma once
// adaptive, strategy guaranteed (vri's extension of Campagnolo, Celes & de
// Figueiredo 2015: GuaranteedAdaptiveIntegrator) on a Vulkan device
// (src/methods/adaptive/adaptive_guaranteed.comp): the ray cut at cell faces and
// transfer-function breakpoints, each smooth piece integrated by Simpson
// steps under the ray's share of the tolerance, one invocation per ray, in
// float. Its step decisions follow float error estimates, so its image is
// not the CPU's to the byte; it meets the tolerance against `exact` as the
// CPU's does (docs/GPU.md). Tolerances below kMinTolerance are refused.
#include <memory>
#include <optional>

#include "compute_kernel.hpp"
#include "gpu_array.hpp"
#include "vulkan_grid_renderer.hpp"

namespace vri::vulkan {

class VulkanGuaranteedAdaptive final : public VulkanGridRenderer {
 public:
  // Float leaves up to 3.7e-5 against `exact` whatever the tolerance (at
  // 1e-5: neghip_spike and fuel_lit, 128^2; the CPU 5e-7): 1e-4 is met.
  static constexpr double kMinTolerance = 1e-4;
  VulkanGuaranteedAdaptive(std::shared_ptr<const VulkanDevice> device, const Scene& scene);
  Image render(const Camera& camera, const RenderOptions& options) const override;

 private:
  VulkanGuaranteedAdaptive(std::shared_ptr<const VulkanDevice> device, const Scene& scene,
                           const FloatTransferFunction& tf);
  GpuTransferFunction tf_;
  GpuBuffer opaque_before_;  // per segment i: the segments before it with tau not zero
  std::optional<GpuEmptySpace> empty_;
  std::optional<ComputeKernel> kernel_;  // made once the arrays are on the device
  float margin_;                         // EmptySpace's: rounding of interpolated scalars
  // The kernel's inputs in binding order, the rays' slot null.
  Bindings inputs() const;
};

}  // namespace vri::vulkan
