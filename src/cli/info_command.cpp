// vri info FILE [--scalars NAME] [--dims X Y Z --type T --endian E] [--bins N]
// [--plot HIST.png] (SPEC §11; issue 20, item 2): what a volume file holds - its
// format, size, sample type, spacing, origin, box and value range - a
// histogram (text, and a PNG plot), and a transfer function to start from.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "scene/scene_json.hpp"
#include "vri/error.hpp"
#include "vri/io.hpp"
#include "vri/scene.hpp"
#include "vri/volume.hpp"

namespace vri::cli {

namespace {

struct InfoArgs {
  std::string file, scalars, type = "uint8", endian = "little", plot;
  std::vector<std::int64_t> dims;
  int bins = 16;
};

std::string vec(Vec3 v) {
  std::ostringstream s;
  s << v.x << " " << v.y << " " << v.z;
  return s.str();
}

// The histogram as bars on a log scale, 512 x 160, white on black.
std::vector<std::byte> plot_png(const Histogram& h) {
  const int W = 512, H = 160;
  std::vector<std::uint8_t> grey(std::size_t(W) * H, 0);
  const double top = std::log1p(double(*std::max_element(h.counts.begin(), h.counts.end())));
  for (int x = 0; x < W; ++x) {
    const std::uint64_t c = h.counts[std::size_t(x) * h.counts.size() / W];
    const int bar = top > 0 ? int(std::lround(std::log1p(double(c)) / top * (H - 1))) : 0;
    for (int y = H - bar; y < H; ++y) grey[std::size_t(y) * W + x] = 220;
  }
  return encode_png(grey, W, H, 1);
}

int run_info(const InfoArgs& a) {
  const VolumeFormat format = volume_format(a.file);
  Volume volume = [&]() -> Volume {
    if (format != VolumeFormat::Raw) {
      if (!a.dims.empty()) throw Error("--dims is for headerless raw files; '" + a.file + "' is " + std::string(format_name(format)));
      return load_volume(a.file, a.scalars);
    }
    if (a.dims.size() != 3)
      throw Error("'" + a.file + "' has no header vri knows: give --dims X Y Z (and --type) to read it as raw; vri reads " +
                  std::string(supported_formats()));
    if (a.endian != "little" && a.endian != "big") throw Error("--endian must be little or big");
    return read_raw_volume(a.file, {a.dims[0], a.dims[1], a.dims[2]}, parse_scalar_type(a.type),
                           a.endian == "big" ? Endian::Big : Endian::Little);
  }();
  const auto [lo, hi] = bounds(volume);
  std::cout << "file: " << a.file << " (" << format_name(format) << ")\n";
  const Histogram h = histogram(volume);  // 256 bins: the plot's, and the suggestion `vri render VOLUME` makes
  if (const auto* g = std::get_if<GridVolume>(&volume)) {
    const auto& d = g->dims();
    std::cout << "kind: regular grid\n"
              << "dims: " << d[0] << " x " << d[1] << " x " << d[2] << " (" << g->size() << " samples)\n"
              << "stored as: " << scalar_type_name(g->type()) << " (" << g->bytes() << " bytes)\n"
              << "spacing: " << vec(g->spacing()) << "\n"
              << "origin: " << vec(g->origin()) << "\n";
  } else {
    const TetMesh& m = std::get<TetMesh>(volume);
    std::cout << "kind: tetrahedral mesh\n"
              << "points: " << m.points().size() << ", tetrahedra: " << m.tets().size() << "\n";
  }
  std::cout << "box: " << vec(lo) << " .. " << vec(hi) << "\n"
            << "range: " << h.lo << " .. " << h.hi << "\n";
  if (a.bins < 1 || a.bins > 256) throw Error("--bins must be 1 .. 256");
  std::cout << "histogram (" << a.bins << " bins; bars on a log scale):\n";
  std::vector<std::uint64_t> coarse(std::size_t(a.bins), 0);
  for (std::size_t i = 0; i < h.counts.size(); ++i) coarse[i * coarse.size() / h.counts.size()] += h.counts[i];
  const double top = std::log1p(double(*std::max_element(coarse.begin(), coarse.end())));
  for (std::size_t i = 0; i < coarse.size(); ++i) {
    const double s0 = h.lo + (h.hi - h.lo) * double(i) / double(coarse.size());
    const int bar = top > 0 ? int(std::lround(std::log1p(double(coarse[i])) / top * 40)) : 0;
    std::cout << "  " << std::setw(12) << s0 << " | " << std::string(std::size_t(bar), '#')
              << std::string(std::size_t(40 - bar), ' ') << " " << coarse[i] << "\n";
  }
  // Every number as it reads back (`vri render VOLUME` renders with exactly this function).
  const TransferFunction tf = suggest_transfer_function(h, length(hi - lo));
  std::cout << "suggested transfer function (a scene's \"transfer_function\", or a presets/ file):\n  "
            << transfer_function_json(tf).dump() << "\n";
  if (!a.plot.empty()) {
    if (std::filesystem::path(a.plot).extension() != ".png") throw Error("--plot must name a .png file");
    write_file_atomically(a.plot, plot_png(h));
    std::cout << "histogram plot: " << a.plot << "\n";
  }
  return 0;
}

}  // namespace

Runner add_info_command(CLI::App& app) {
  auto args = std::make_shared<InfoArgs>();
  CLI::App* cmd = app.add_subcommand("info", "Describe a volume file: size, type, spacing, range, histogram, a transfer function to start from");
  cmd->add_option("file", args->file, "Volume or mesh file")->required();
  cmd->add_option("--scalars", args->scalars, "VTK files: the point array to read (default: the active or first)");
  cmd->add_option("--dims", args->dims, "Headerless raw files: X Y Z")->expected(3);
  cmd->add_option("--type", args->type, "Headerless raw files: the sample type (default uint8)");
  cmd->add_option("--endian", args->endian, "Headerless raw files: little (default) or big");
  cmd->add_option("--bins", args->bins, "Bins of the text histogram (1..256, default 16)");
  cmd->add_option("--plot", args->plot, "Also write the histogram (256 bins, log scale) as a PNG");
  return [args] { return run_info(*args); };
}

}  // namespace vri::cli
