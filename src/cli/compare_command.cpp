// vri compare A.npy B.npy [--tolerance E] [--max-share F]: per channel, the
// share of pixels whose absolute difference exceeds E, the RMS and the
// maximum difference, and the pixels whose difference is NaN; exit status 0
// within, 1 when a channel has more than the share F (default 0) of pixels
// over E (a NaN fails whatever the share), 2 on an error: an unreadable file, shapes
// that differ, a bad flag (SPEC §12).
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "vri/error.hpp"
#include "vri/io.hpp"
#include "vri/render.hpp"

namespace vri::cli {

namespace {

struct CompareArgs {
  std::string a, b;
  double tolerance = 1.0 / 255.0;
  double max_share = 0;
};

int run_compare(const CompareArgs& args) {
  if (!(args.tolerance >= 0)) throw Error("--tolerance: expected a number >= 0, found " + format_g(args.tolerance));
  if (!(args.max_share >= 0 && args.max_share <= 1))
    throw Error("--max-share: expected a number in [0, 1], found " + format_g(args.max_share));
  const NpyArray a = read_npy(args.a), b = read_npy(args.b);
  if (a.shape != b.shape) throw Error("'" + args.a + "' and '" + args.b + "' have different shapes");
  const int channels = a.shape.size() >= 3 ? int(a.shape.back()) : 1;
  const auto diff = compare_images(a.data, b.data, channels, args.tolerance);
  static const char* rgba[] = {"r", "g", "b", "a"};
  std::printf("channel  share_over(>%g)  rms           max           nan\n", args.tolerance);
  for (int c = 0; c < channels; ++c) {
    const std::string name = channels == 4 ? rgba[c] : std::to_string(c);
    std::printf("%-7s  %-15.6f  %-12.6e  %-12.6e  %zu\n", name.c_str(), diff[c].share_over, diff[c].rms, diff[c].max,
                diff[c].nan);
  }
  bool over = false;
  for (int c = 0; c < channels; ++c) over = over || !(diff[c].share_over <= args.max_share) || diff[c].nan > 0;
  return over ? 1 : 0;
}

}  // namespace

Runner add_compare_command(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand("compare", "Per-channel differences between two .npy images");
  cmd->add_option("a", args->a, "First image (.npy)")->required();
  cmd->add_option("b", args->b, "Second image (.npy)")->required();
  cmd->add_option("--tolerance", args->tolerance, "Difference counted as over (default 1/255)");
  cmd->add_option("--max-share", args->max_share, "Share of pixels allowed over the tolerance (default 0)");
  // An error is exit 2 here, apart from 1 for "over" (SPEC §12).
  return [args] {
    try {
      return run_compare(*args);
    } catch (const std::exception& e) {
      std::cerr << "vri: error: " << message_line(e.what()) << "\n";
      return 2;
    }
  };
}

}  // namespace vri::cli
