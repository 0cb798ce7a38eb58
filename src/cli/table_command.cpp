// vri table --tf TF.json --size N [--order 1|2] [--length L]
//   [--lengths M --max-length LMAX] [--builder NAME] -o TABLE.npy   (SPEC §10)
//   [--steps K] [--accumulation 8bit|12bit|fp16|fp32]               (sliced only)
//   [--iterations K]                                                (order 2 only)
//   [--backend cpu|vulkan]                                          (SPEC §11; docs/GPU.md)
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "vri/error.hpp"
#include "vri/io.hpp"
#include "vri/scene.hpp"
#include "vri/render.hpp"

namespace vri::cli {

namespace {

struct TableArgs {
  std::string tf, output;
  TableRequest request;
};

int run_table(const TableArgs& args) {
  if (std::filesystem::path(args.output).extension() != ".npy")
    throw Error("output '" + args.output + "' must end in .npy");
  const BuiltTable table = build_table(load_transfer_function(args.tf), args.request);
  write_npy(args.output, table.shape, table.data);
  std::string shape;
  for (std::size_t i = 0; i + 1 < table.shape.size(); ++i) shape += (i ? "x" : "") + std::to_string(table.shape[i]);
  std::cerr << "vri: built a " << shape << " table with '" << table.builder << "' in " << table.seconds << " s -> "
            << args.output << "\n";
  return 0;
}

}  // namespace

Runner add_table_command(CLI::App& app) {
  auto args = std::make_shared<TableArgs>();
  CLI::App* cmd = app.add_subcommand("table", "Build a pre-integration table as .npy (float32 RGBA)");
  cmd->add_option("--tf", args->tf, "Transfer function JSON file")->required();
  cmd->add_option("--size", args->request.size, "Entries per scalar axis N (default 256)");
  cmd->add_option("--order", args->request.order, "Pre-integration order: 1 (default) or 2, shape (N, N, N, 4)");
  cmd->add_option("--length", args->request.length, "Slab length in world units (default 1)");
  cmd->add_option("--lengths", args->request.lengths, "Number of slab lengths M: shape (M, N, N, 4)");
  cmd->add_option("--max-length", args->request.max_length, "Largest slab length LMAX (with --lengths)");
  cmd->add_option("--builder", args->request.builder,
                  "order 1: brute, incremental, sliced, engel or exact (default incremental); order 2: plain, fast (default) or exact (small N: every entry to 1e-7)");
  cmd->add_option("--iterations", args->request.iterations, "order 2: chords per slab K, 1..4096 (default 8)");
  cmd->add_option("--steps", args->request.steps, "sliced: integration steps (default 2N)");
  cmd->add_option("--accumulation", args->request.accumulation, "sliced: 8bit, 12bit, fp16 or fp32 (default fp32)");
  cmd->add_option("--backend", args->request.backend,
                  "cpu (default) or vulkan: build on the GPU (order 1: sliced, fp32; order 2: fast)");
  cmd->add_option("-o,--output", args->output, "Output table (.npy)")->required();
  return [args] { return run_table(*args); };
}

}  // namespace vri::cli
