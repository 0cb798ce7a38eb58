// vri table --tf TF.json --size N [--order 1|2] [--length L]
//   [--lengths M --max-length LMAX] [--builder NAME] -o TABLE.npy   (SPEC §10)
//   [--steps K] [--accumulation 8bit|12bit|fp16|fp32]               (sliced only)
//   [--iterations K]                                                (order 2 only)
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "commands.hpp"
#include "vri/core/error.hpp"
#include "vri/io/npy.hpp"
#include "vri/scene/scene.hpp"
#include "vri/tables/second_order_table.hpp"
#include "vri/tables/sliced_builder.hpp"
#include "vri/tables/table_builder.hpp"

namespace vri::cli {

namespace {

struct TableArgs {
  std::string tf, output, accumulation = "fp32";
  std::optional<std::string> builder;
  int size = 256, order = 1, steps = 0;
  double length = 1;
  std::optional<int> lengths, iterations;
  std::optional<double> max_length;
};

void report(const std::string& what, std::string_view builder, double seconds, const std::string& output) {
  std::cerr << "vri: built a " << what << " table with '" << builder << "' in " << seconds << " s -> " << output
            << "\n";
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Order 2 (El Hajjar et al. 2008): shape (N, N, N, 4) indexed [s_f, s_m, s_b].
int run_second_order(const TableArgs& args) {
  if (args.lengths || args.max_length) throw Error("--lengths and --max-length are for --order 1");
  const DiscreteTf discrete(load_transfer_function(args.tf), args.size);
  const auto builder = make_second_order_builder(args.builder.value_or("fast"));
  const auto start = std::chrono::steady_clock::now();
  const SecondOrderTable table = builder->build(discrete, args.length, args.iterations.value_or(64));
  const double seconds = seconds_since(start);
  const std::size_t n = args.size;
  write_npy(args.output, {n, n, n, 4}, {table.data(), table.bytes() / sizeof(float)});
  report(std::to_string(n) + "^3", builder->name(), seconds, args.output);
  return 0;
}

int run_table(const TableArgs& args) {
  if (std::filesystem::path(args.output).extension() != ".npy")
    throw Error("output '" + args.output + "' must end in .npy");
  if (args.order == 2) return run_second_order(args);
  if (args.order != 1) throw Error("--order must be 1 or 2, got " + std::to_string(args.order));
  if (args.iterations) throw Error("--iterations is for --order 2");
  if (args.lengths.has_value() != args.max_length.has_value())
    throw Error("--lengths and --max-length go together");
  const TransferFunction tf = load_transfer_function(args.tf);
  const DiscreteTf discrete(tf, args.size);
  const std::string builder_name = args.builder.value_or("incremental");
  const std::unique_ptr<TableBuilder> builder =
      builder_name == "sliced" ? std::make_unique<SlicedBuilder>(args.steps, parse_accumulation(args.accumulation))
                               : make_table_builder(builder_name);
  const std::size_t n = args.size;

  const auto start = std::chrono::steady_clock::now();
  std::vector<std::size_t> shape;
  std::vector<float> data;
  if (args.lengths) {
    const LengthTable table = build_length_table(*builder, discrete, *args.lengths, *args.max_length);
    shape = {static_cast<std::size_t>(*args.lengths), n, n, 4};
    data = table.data();
  } else {
    const PreintegrationTable table = builder->build(discrete, args.length);
    shape = {n, n, 4};
    data.assign(table.data().begin(), table.data().end());
  }
  const double seconds = seconds_since(start);
  write_npy(args.output, shape, data);
  report((args.lengths ? std::to_string(*args.lengths) + "x" : "") + std::to_string(n) + "x" + std::to_string(n),
         builder->name(), seconds, args.output);
  return 0;
}

}  // namespace

Runner add_table_command(CLI::App& app) {
  auto args = std::make_shared<TableArgs>();
  CLI::App* cmd = app.add_subcommand("table", "Build a pre-integration table as .npy (float32 RGBA)");
  cmd->add_option("--tf", args->tf, "Transfer function JSON file")->required();
  cmd->add_option("--size", args->size, "Entries per scalar axis N (default 256)");
  cmd->add_option("--order", args->order, "Pre-integration order: 1 (default) or 2, shape (N, N, N, 4)");
  cmd->add_option("--length", args->length, "Slab length in world units (default 1)");
  cmd->add_option("--lengths", args->lengths, "Number of slab lengths M: shape (M, N, N, 4)");
  cmd->add_option("--max-length", args->max_length, "Largest slab length LMAX (with --lengths)");
  cmd->add_option("--builder", args->builder,
                  "order 1: brute, incremental, sliced, engel or exact (default incremental); order 2: plain or fast (default)");
  cmd->add_option("--iterations", args->iterations, "order 2: sub-steps per slab K, 1..4096 (default 64)");
  cmd->add_option("--steps", args->steps, "sliced: integration steps (default 2N)");
  cmd->add_option("--accumulation", args->accumulation, "sliced: 8bit, 12bit, fp16 or fp32 (default fp32)");
  cmd->add_option("-o,--output", args->output, "Output table (.npy)")->required();
  return [args] { return run_table(*args); };
}

}  // namespace vri::cli
