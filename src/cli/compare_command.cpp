// vri compare A.npy B.npy [--tolerance E]: per channel, the share of pixels
// whose absolute difference exceeds E, the RMS and the maximum difference.
#include <cstdio>
#include <memory>
#include <string>

#include "commands.hpp"
#include "vri/core/error.hpp"
#include "vri/io/npy.hpp"
#include "vri/render/image_compare.hpp"

namespace vri::cli {

namespace {

struct CompareArgs {
  std::string a, b;
  double tolerance = 1.0 / 255.0;
};

int run_compare(const CompareArgs& args) {
  if (!(args.tolerance >= 0)) throw Error("--tolerance must be >= 0");
  const NpyArray a = read_npy(args.a), b = read_npy(args.b);
  if (a.shape != b.shape) throw Error("'" + args.a + "' and '" + args.b + "' have different shapes");
  const int channels = a.shape.size() >= 3 ? int(a.shape.back()) : 1;
  const auto diff = compare_images(a.data, b.data, channels, args.tolerance);
  static const char* rgba[] = {"r", "g", "b", "a"};
  std::printf("channel  share_over(>%g)  rms           max\n", args.tolerance);
  for (int c = 0; c < channels; ++c) {
    const std::string name = channels == 4 ? rgba[c] : std::to_string(c);
    std::printf("%-7s  %-15.6f  %-12.6e  %-12.6e\n", name.c_str(), diff[c].share_over, diff[c].rms, diff[c].max);
  }
  return 0;
}

}  // namespace

Runner add_compare_command(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand("compare", "Per-channel differences between two .npy images");
  cmd->add_option("a", args->a, "First image (.npy)")->required();
  cmd->add_option("b", args->b, "Second image (.npy)")->required();
  cmd->add_option("--tolerance", args->tolerance, "Difference counted as over (default 1/255)");
  return [args] { return run_compare(*args); };
}

}  // namespace vri::cli
