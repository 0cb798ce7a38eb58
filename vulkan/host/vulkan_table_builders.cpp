#include "vulkan_table_builders.hpp"
#include "table_builder_push_constants.h"

#include <cstdint>
#include <span>
#include <memory>
#include <string>
#include <vector>

#include "gpu_array.hpp"
#include "gpu_discrete_tf.hpp"
#include "vri/error.hpp"
#include "tables/incremental_builder.hpp"
#include "tables/second_order_weighted.hpp"

namespace vri::vulkan {

namespace {

const std::uint32_t kSlicedSpirv[] = {
#include "sliced_table.spv.inc"
};
const std::uint32_t kIncrementalPiecesSpirv[] = {
#include "incremental_pieces.spv.inc"
};
const std::uint32_t kIncrementalChainsSpirv[] = {
#include "incremental_chains.spv.inc"
};
const std::uint32_t kIncrementalJoinsSpirv[] = {
#include "incremental_joins.spv.inc"
};
const std::uint32_t kSecondOrderSpirv[] = {
#include "second_order_table.spv.inc"
};

struct SlicedParams {
  VRI_SLICED_TABLE_PUSH_CONSTANTS
};

struct IncrementalParams {
  VRI_INCREMENTAL_TABLE_PUSH_CONSTANTS
};
// incremental_table.comp's bindings: the table (four), the transfer function (three), six scratch arrays.
constexpr int kIncrementalBindings = GpuArray::kParts + 3 + 6;

struct SecondOrderParams {
  VRI_SECOND_ORDER_TABLE_PUSH_CONSTANTS
};

std::uint32_t groups_of_64(int n) { return static_cast<std::uint32_t>((n + 63) / 64); }

}  // namespace

VulkanSlicedBuilder::VulkanSlicedBuilder(std::shared_ptr<const VulkanDevice> device, int steps)
    : device_(std::move(device)), steps_(steps), kernel_(device_, kSlicedSpirv, GpuArray::kParts + 3, sizeof(SlicedParams)) {
  if (steps < 0 || steps > (1 << 20))
    throw Error("sliced: steps must be in [0, 1048576], got " + std::to_string(steps));
}

PreintegrationTable VulkanSlicedBuilder::build(const DiscreteTf& tf, double length) const {
  check_slab_length(length);
  const int n = tf.size(), steps = steps_ > 0 ? steps_ : 2 * n;
  PreintegrationTable table(tf.axis(), length);
  const GpuDiscreteTf on_device(device_, tf);
  const std::size_t floats = table.data().size();
  const GpuArray entries(device_, floats * sizeof(float), "the pre-integration table");
  const SlicedParams p{device_->part_shift(), n, steps, static_cast<float>(length / steps), 0};
  Bindings b;
  b.add(entries).add(&on_device.samples).add(&on_device.sub_begin).add(&on_device.subs);
  kernel_.run(groups_of_64(n), static_cast<std::uint32_t>(n), b.list(), &p);
  entries.download(std::as_writable_bytes(std::span<float>(table.entry(0, 0), floats)));
  return table;
}

VulkanIncrementalBuilder::VulkanIncrementalBuilder(std::shared_ptr<const VulkanDevice> device)
    : device_(std::move(device)),
      pieces_(device_, kIncrementalPiecesSpirv, kIncrementalBindings, sizeof(IncrementalParams)),
      chains_(device_, kIncrementalChainsSpirv, kIncrementalBindings, sizeof(IncrementalParams)),
      joins_(device_, kIncrementalJoinsSpirv, kIncrementalBindings, sizeof(IncrementalParams)) {}

PreintegrationTable VulkanIncrementalBuilder::build(const DiscreteTf& tf, double length) const {
  check_slab_length(length);
  const int n = tf.size();
  PreintegrationTable table(tf.axis(), length);
  const GpuDiscreteTf on_device(device_, tf);
  const std::size_t floats = table.data().size();
  const GpuArray entries(device_, floats * sizeof(float), "the pre-integration table");
  const std::size_t scratch_bytes = static_cast<std::size_t>(n - 1) * (n - 1) * 4 * sizeof(float);
  std::vector<std::unique_ptr<GpuBuffer>> scratch;
  for (int i = 0; i < 6; ++i)
    scratch.push_back(std::make_unique<GpuBuffer>(device_, scratch_bytes, "the incremental builder's scratch"));
  const IncrementalParams p{device_->part_shift(), n, static_cast<float>(length)};
  Bindings b;
  b.add(entries).add(&on_device.samples).add(&on_device.sub_begin).add(&on_device.subs);
  for (const auto& s : scratch) b.add(s.get());
  const auto diagonals = static_cast<std::uint32_t>(n - 1);
  pieces_.run(groups_of_64(n - 1), diagonals, b.list(), &p);
  chains_.run(groups_of_64(n - 1), diagonals, b.list(), &p);
  joins_.run(groups_of_64(n), static_cast<std::uint32_t>(n), b.list(), &p);
  entries.download(std::as_writable_bytes(std::span<float>(table.entry(0, 0), floats)));
  return table;
}

VulkanSecondOrderBuilder::VulkanSecondOrderBuilder(std::shared_ptr<const VulkanDevice> device)
    : device_(std::move(device)),
      kernel_(device_, kSecondOrderSpirv, GpuArray::kParts + 1, sizeof(SecondOrderParams)) {}

SecondOrderTable VulkanSecondOrderBuilder::build(const DiscreteTf& tf, double length, int iterations) const {
  check_slab_length(length);
  check_iterations(iterations);
  SecondOrderTable table(tf.axis(), length, iterations);
  const int n = tf.size();
  const PreintegrationTable chords = IncrementalBuilder().build(tf, length / iterations);
  const GpuBuffer chords_on_device(device_, std::as_bytes(chords.data()), "the chords' table");
  const std::size_t floats = table.bytes() / sizeof(float);
  const GpuArray entries(device_, table.bytes(), "the second-order table");
  const SecondOrderParams p{device_->part_shift(), n, iterations};
  Bindings b;
  b.add(entries).add(&chords_on_device);
  kernel_.run(groups_of_64(n), static_cast<std::uint32_t>(n), b.list(), &p, static_cast<std::uint32_t>(n));
  entries.download(std::as_writable_bytes(std::span<float>(table.entry(0, 0, 0), floats)));
  write_straight_entries(tf, table);  // as the CPU's fast builder
  return table;
}

SecondOrderWeightedTables VulkanSecondOrderBuilder::build_weighted(const DiscreteTf&, double, int) const {
  throw Error("vulkan: the weighted second-order tables (interpolated lighting) are built on the CPU");
}

}  // namespace vri::vulkan
