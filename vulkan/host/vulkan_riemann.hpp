#pragma once
// riemann on a Vulkan device (vulkan/shaders/riemann.comp): the CPU float
// path's sum (src/integrators/float_riemann.hpp) at the same sample
// positions - rays set up on the host (ray_setup.hpp), one invocation per
// pixel - lit or not, with jitter and early termination as on the CPU. Skipped samples
// (empty space) add exactly nothing there, so the GPU takes them all and
// gets the same sum.
#include <memory>
#include <optional>

#include "compute_kernel.hpp"
#include "gpu_scene_data.hpp"
#include "vri/render/backend.hpp"
#include "vri/scene/scene.hpp"

namespace vri::vulkan {

class VulkanRiemann final : public GpuSceneRenderer {
 public:
  VulkanRiemann(std::shared_ptr<const VulkanDevice> device, const Scene& scene);
  Image render(const Camera& camera, const RenderOptions& options) const override;
  std::string device_name() const override { return "vulkan: " + device_->info().name; }

 private:
  std::shared_ptr<const VulkanDevice> device_;
  const Scene& scene_;
  double h_;  // world units
  GpuVolume volume_;
  GpuTransferFunction tf_;
  std::optional<HeadlightShader> shader_;  // lit: the gradients
  std::optional<GpuShading> shading_;
  ComputeKernel kernel_;
};

}  // namespace vri::vulkan
