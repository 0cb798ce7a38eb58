#pragma once
// riemann on a Vulkan device (src/methods/riemann/riemann.comp): the CPU float
// path's sum (src/methods/riemann/float_riemann.hpp) at the same sample
// positions - each ray made on the GPU from the camera (camera_rays.glsl), one invocation per
// pixel - lit or not, with jitter and early termination as on the CPU. Skipped samples
// (empty space) add exactly nothing there, so the GPU takes them all and
// gets the same sum.
#include <memory>
#include <optional>

#include "compute_kernel.hpp"
#include "gpu_array.hpp"
#include "vulkan_grid_renderer.hpp"

namespace vri::vulkan {

class VulkanRiemann final : public VulkanGridRenderer {
 public:
  VulkanRiemann(std::shared_ptr<const VulkanDevice> device, const Scene& scene);
  Image render(const Camera& camera, const RenderOptions& options) const override;

 private:
  double h_;  // world units
  GpuTransferFunction tf_;
  std::optional<GpuEmptySpace> empty_;  // the macro cells the CPU would leap over
  std::optional<ComputeKernel> kernel_;  // made once the arrays are on the device
  // The kernel's inputs in binding order, the rays' slot null.
  Bindings inputs() const;
};

}  // namespace vri::vulkan
