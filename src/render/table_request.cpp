#include "vri/render.hpp"

#include <chrono>
#include <memory>

#include "vri/error.hpp"
#include "vri/methods.hpp"  // kDefaultSecondOrderIterations
#include "tables/second_order_table.hpp"
#include "tables/sliced_builder.hpp"
#include "tables/table_builder.hpp"

namespace vri {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Whether the table is built on the GPU (`backend`); vri::Error unless cpu or vulkan.
bool gpu(const TableRequest& r) { return parse_backend(r.backend) == Backend::Vulkan; }

template <class Builder>
std::string builder_name(const Builder& builder, const TableRequest& r) {
  return std::string(builder.name()) + (gpu(r) ? " (vulkan)" : "");
}

BuiltTable second_order(const TransferFunction& tf, const TableRequest& r) {
  if (r.lengths || r.max_length) throw Error("--lengths and --max-length are for --order 1");
  const DiscreteTf discrete(tf, r.size);  // SPEC §10: the control points' span
  const std::string name = r.builder.value_or("fast");
  const auto builder = gpu(r) ? make_vulkan_second_order_builder(name) : make_second_order_builder(name);
  const auto start = std::chrono::steady_clock::now();
  auto table = std::make_shared<const SecondOrderTable>(builder->build(discrete, r.length, r.iterations.value_or(kDefaultSecondOrderIterations)));
  const double seconds = seconds_since(start);
  const std::size_t n = r.size;
  return {{n, n, n, 4}, {table->data(), table->bytes() / sizeof(float)}, table, builder_name(*builder, r), seconds};
}

}  // namespace

BuiltTable build_table(const TransferFunction& tf, const TableRequest& r) {
  if (r.order == 2) return second_order(tf, r);
  if (r.order != 1) throw Error("--order must be 1 or 2, got " + std::to_string(r.order));
  if (r.iterations) throw Error("--iterations is for --order 2");
  if (r.lengths.has_value() != r.max_length.has_value()) throw Error("--lengths and --max-length go together");
  const DiscreteTf discrete(tf, r.size);  // SPEC §10: the control points' span
  // One default on both backends: incremental, exact to 1e-9 on the CPU and
  // 2e-6 on the GPU, where sliced is 5.8e-4 from exact (issue 46).
  const std::string name = r.builder.value_or("incremental");
  if (gpu(r) && parse_accumulation(r.accumulation) != Accumulation::Single)
    throw Error("--backend vulkan builds in fp32; --accumulation " + r.accumulation + " simulates a frame buffer on the CPU");
  const std::unique_ptr<TableBuilder> builder =
      gpu(r)            ? make_vulkan_table_builder(name, r.steps)
      : name == "sliced" ? std::make_unique<SlicedBuilder>(r.steps, parse_accumulation(r.accumulation))
                         : make_table_builder(name);
  const std::size_t n = r.size;
  const auto start = std::chrono::steady_clock::now();
  BuiltTable out;
  if (r.lengths) {
    auto data = std::make_shared<const std::vector<float>>(
        build_length_table(*builder, discrete, *r.lengths, *r.max_length).data());
    out.shape = {static_cast<std::size_t>(*r.lengths), n, n, 4};
    out.data = *data;
    out.owner = data;
  } else {
    auto table = std::make_shared<const PreintegrationTable>(builder->build(discrete, r.length));
    out.shape = {n, n, 4};
    out.data = table->data();
    out.owner = table;
  }
  out.seconds = seconds_since(start);
  out.builder = builder_name(*builder, r);
  return out;
}

}  // namespace vri
