#pragma once
// preint2-dual on a Vulkan device (src/methods/preint2_dual/preint2_dual.comp): the
// CPU float path's cell-by-cell march (src/methods/preint2_dual/dual_march.hpp) with
// the cell walk in double-float, over the same (l, s_f, s_m, s_b) tables -
// built on the host as Preint2DualIntegrator builds them, uploaded once,
// slice after slice. Lit in both modes; empty macro cells not sampled;
// early termination.
#include <array>
#include <memory>
#include <optional>

#include "compute_kernel.hpp"
#include "gpu_array.hpp"
#include "vulkan_grid_renderer.hpp"
#include "tables/discrete_tf.hpp"
#include "tables/second_order_table.hpp"

namespace vri::vulkan {

class VulkanPreint2Dual final : public VulkanGridRenderer {
 public:
  VulkanPreint2Dual(std::shared_ptr<const VulkanDevice> device, const Scene& scene);
  Image render(const Camera& camera, const RenderOptions& options) const override;

 private:
  DiscreteTf tf_;
  ScalarAxis axis_;
  double max_length_ = 0;  // world units
  int lengths_ = 0;
  int mode_ = 0;  // the shader's p.lit: 0 unlit, 1 sampled, 2 interpolated
  // The table, or the full, middle and back weighted tables, each its slices one after another.
  std::array<std::optional<GpuArray>, 3> tables_;
  std::optional<GpuEmptySpace> empty_;
  std::optional<ComputeKernel> kernel_;
  Bindings inputs() const;
};

}  // namespace vri::vulkan
