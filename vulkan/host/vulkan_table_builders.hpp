#pragma once
// Pre-integration tables built on a Vulkan device (issue 22, item 3), behind
// the CPU builders' interfaces, so `vri table --backend vulkan`, the Python
// vri.table and build_length_table use them as any builder:
//   VulkanSlicedBuilder: Roettger & Ertl 2002's slice-by-slice first-order
//     table (shaders/sliced_table.comp), SlicedBuilder's with float32
//     accumulation; a table of M lengths is M of its dispatches.
//   VulkanIncrementalBuilder: Lum, Wilson & Ma 2004's incremental subrange
//     integration (shaders/incremental_table.comp), IncrementalBuilder's in
//     float: the pieces, the prefix chains within each bin, the joins, all
//     diagonals at once.
//   VulkanSecondOrderBuilder: El Hajjar et al. 2008's second-order table
//     (shaders/second_order_table.comp), FastSecondOrderBuilder's: the
//     chords' first-order table built on the host (IncrementalBuilder,
//     O(N^2)), the O(N^3 K) chords on the device.
#include <memory>

#include "compute_kernel.hpp"
#include "tables/second_order_table.hpp"
#include "tables/table_builder.hpp"

namespace vri::vulkan {

class VulkanSlicedBuilder final : public TableBuilder {
 public:
  // steps = 0: 2 N steps. Throws vri::Error unless 0 <= steps <= 1 << 20.
  VulkanSlicedBuilder(std::shared_ptr<const VulkanDevice> device, int steps);
  std::string_view name() const override { return "sliced"; }
  double work(int n) const override { return double(steps_ > 0 ? steps_ : 2 * n) * n * n; }  // as SlicedBuilder
  PreintegrationTable build(const DiscreteTf& tf, double length) const override;

 private:
  std::shared_ptr<const VulkanDevice> device_;
  int steps_;
  ComputeKernel kernel_;
};

class VulkanIncrementalBuilder final : public TableBuilder {
 public:
  explicit VulkanIncrementalBuilder(std::shared_ptr<const VulkanDevice> device);
  std::string_view name() const override { return "incremental"; }
  double work(int n) const override { return 4.0 * n * n; }  // as IncrementalBuilder
  // vri::Error when its scratch ((N-1)^2 entries, six times) exceeds a storage buffer.
  PreintegrationTable build(const DiscreteTf& tf, double length) const override;

 private:
  std::shared_ptr<const VulkanDevice> device_;
  ComputeKernel pieces_, chains_, joins_;
};

class VulkanSecondOrderBuilder final : public SecondOrderBuilder {
 public:
  explicit VulkanSecondOrderBuilder(std::shared_ptr<const VulkanDevice> device);
  std::string_view name() const override { return "fast"; }
  SecondOrderTable build(const DiscreteTf& tf, double length, int iterations) const override;
  // Not on the GPU yet: vri::Error.
  SecondOrderWeightedTables build_weighted(const DiscreteTf& tf, double length, int iterations) const override;

 private:
  std::shared_ptr<const VulkanDevice> device_;
  ComputeKernel kernel_;
};

}  // namespace vri::vulkan
