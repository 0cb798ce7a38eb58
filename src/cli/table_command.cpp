// vri table --tf TF.json --size N [--order 1|2] [--length L]
//   [--lengths M --max-length LMAX] [--builder NAME] -o TABLE.npy   (SPEC §10)
//   [--steps K] [--accumulation 8bit|12bit|fp16|fp32]               (sliced only)
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "commands.hpp"
#include "vri/core/error.hpp"
#include "vri/io/npy.hpp"
#include "vri/scene/scene.hpp"
#include "vri/tables/sliced_builder.hpp"
#include "vri/tables/table_builder.hpp"

namespace vri::cli {

namespace {

struct TableArgs {
  std::string tf, output, builder = "incremental", accumulation = "fp32";
  int size = 256, order = 1, steps = 0;
  double length = 1;
  std::optional<int> lengths;
  std::optional<double> max_length;
};

int run_table(const TableArgs& args) {
  if (std::filesystem::path(args.output).extension() != ".npy")
    throw Error("output '" + args.output + "' must end in .npy");
  if (args.order != 1) throw Error("--order " + std::to_string(args.order) + " is not implemented (only 1)");
  if (args.lengths.has_value() != args.max_length.has_value())
    throw Error("--lengths and --max-length go together");
  const TransferFunction tf = load_transfer_function(args.tf);
  const DiscreteTf discrete(tf, args.size);
  const std::unique_ptr<TableBuilder> builder =
      args.builder == "sliced" ? std::make_unique<SlicedBuilder>(args.steps, parse_accumulation(args.accumulation))
                               : make_table_builder(args.builder);
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
    data = table.data();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_npy(args.output, shape, data);
  std::cerr << "vri: built a " << (args.lengths ? std::to_string(*args.lengths) + "x" : "") << n << "x" << n
            << " table with '" << builder->name() << "' in " << seconds << " s -> " << args.output << "\n";
  return 0;
}

}  // namespace

Runner add_table_command(CLI::App& app) {
  auto args = std::make_shared<TableArgs>();
  CLI::App* cmd = app.add_subcommand("table", "Build a pre-integration table as .npy (float32 RGBA)");
  cmd->add_option("--tf", args->tf, "Transfer function JSON file")->required();
  cmd->add_option("--size", args->size, "Entries per scalar axis N (default 256)");
  cmd->add_option("--order", args->order, "Pre-integration order (1)");
  cmd->add_option("--length", args->length, "Slab length in world units (default 1)");
  cmd->add_option("--lengths", args->lengths, "Number of slab lengths M: shape (M, N, N, 4)");
  cmd->add_option("--max-length", args->max_length, "Largest slab length LMAX (with --lengths)");
  cmd->add_option("--builder", args->builder, "brute, incremental, sliced or engel (default incremental)");
  cmd->add_option("--steps", args->steps, "sliced: integration steps (default 2N)");
  cmd->add_option("--accumulation", args->accumulation, "sliced: 8bit, 12bit, fp16 or fp32 (default fp32)");
  cmd->add_option("-o,--output", args->output, "Output table (.npy)")->required();
  return [args] { return run_table(*args); };
}

}  // namespace vri::cli
