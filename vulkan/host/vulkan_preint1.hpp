#pragma once
// preint1 on a Vulkan device (vulkan/shaders/preint1.comp): the CPU float
// path's march (src/integrators/float_march.hpp) over the same table - built
// on the host by the scene's builder, uploaded once - at the same sample
// positions, with the partial last slab integrated exactly on the host
// (ray_setup.hpp). Empty slabs read all-zero entries and add exactly
// nothing, so the GPU marches through them and gets the CPU's sum. Lit in
// both modes (sampled, interpolated), as the CPU's float path.
#include <memory>
#include <optional>

#include "compute_kernel.hpp"
#include "vulkan_grid_renderer.hpp"
#include "vri/tables/discrete_tf.hpp"
#include "vri/tables/preintegration_table.hpp"
#include "vri/tables/weighted_tables.hpp"
#include "vri/volume/float_sampler.hpp"

namespace vri::detail {
class FloatShading;  // src/integrators/float_shading.hpp
}

namespace vri::vulkan {

class VulkanPreint1 final : public VulkanGridRenderer {
 public:
  VulkanPreint1(std::shared_ptr<const VulkanDevice> device, const Scene& scene);
  ~VulkanPreint1() override;
  Image render(const Camera& camera, const RenderOptions& options) const override;

 private:
  double h_;  // world units
  DiscreteTf tf_;
  PreintegrationTable table_;
  GpuBuffer table_buffer_;
  // Lit: the shader and its gradients, the float shading the host's last
  // slabs use, the weighted tables (interpolated) and their copies on the device.
  std::optional<HeadlightShader> shader_;
  std::optional<GpuShading> shading_;
  FloatSampler sampler_;
  std::unique_ptr<detail::FloatShading> float_shading_;
  std::optional<WeightedTables> weighted_;
  std::optional<GpuBuffer> weighted_front_, weighted_back_;
  ComputeKernel kernel_;
};

}  // namespace vri::vulkan
