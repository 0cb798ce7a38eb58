#pragma once
// preint1 and preint2 on a Vulkan device (src/methods/preint/preint.comp, built
// once for each): the CPU float path's march (src/methods/preint/float_march.hpp)
// over the same tables - built on the host by the scene's builder as the CPU
// integrators build them, uploaded once - at the same sample positions, with
// the partial last slab integrated exactly on the host (add_partial_slabs).
// Empty slabs read all-zero entries and add exactly nothing, so the GPU
// marches through them and gets the CPU's sum. Lit in both modes (sampled,
// interpolated), as the CPU's float path.
#include <array>
#include <memory>
#include <optional>
#include <span>

#include "compute_kernel.hpp"
#include "gpu_array.hpp"
#include "pixel_kernel.hpp"  // PixelSpan
#include "float_march.hpp"  // FloatLighting
#include "vulkan_grid_renderer.hpp"
#include "tables/discrete_tf.hpp"
#include "tables/float_lookup.hpp"
#include "tables/preintegration_table.hpp"
#include "tables/second_order_table.hpp"
#include "tables/second_order_weighted.hpp"
#include "tables/weighted_tables.hpp"
#include "volume/float_sampler.hpp"

namespace vri::vulkan {

class VulkanPreint final : public VulkanGridRenderer {
 public:
  // The scene's method is preint1 or preint2.
  VulkanPreint(std::shared_ptr<const VulkanDevice> device, const Scene& scene);
  ~VulkanPreint() override;
  Image render(const Camera& camera, const RenderOptions& options) const override;

 private:
  int steps_;  // a slab's steps: 1 (preint1) or 2 (preint2)
  double h_;   // world units
  DiscreteTf tf_;
  // The host's tables, the one the scene's lighting needs: preint1's table
  // or its front and back weighted tables; preint2's table or its full,
  // middle and back weighted tables.
  std::optional<PreintegrationTable> table1_;
  std::optional<WeightedTables> weighted1_;
  std::optional<SecondOrderTable> table2_;
  std::optional<SecondOrderWeightedTables> weighted2_;
  std::optional<FloatAxis> axis_;
  std::array<const float*, 3> tables_{};   // the shader's table, weighted1 and weighted2 (null: none)
  std::array<std::optional<GpuArray>, 3> on_device_;
  // Lit: the shader and its gradients, the float shading the host's last slabs use.
  FloatSampler sampler_;
  std::unique_ptr<detail::FloatShading> float_shading_;
  detail::FloatLighting lighting_;  // as the CPU's float march lights its last slabs
  std::optional<GpuEmptySpace> empty_;   // the macro cells the CPU would leap over
  std::optional<ComputeKernel> kernel_;  // made once the arrays are on the device
  // The kernel's inputs in binding order, the rays' slot null.
  Bindings inputs() const;
  // The partial last slabs of the span's pixels composited behind what the
  // kernel left in `rgba`, as the CPU's finish_float: `tails` holds, a pixel,
  // the whole slabs the kernel composited (int bits; -1: none to add) and its
  // T, r, g, b in double-float.
  void add_partial_slabs(const Camera& camera, PixelSpan span, std::span<float> rgba, std::span<const float> tails,
                         int threads) const;
};

}  // namespace vri::vulkan
