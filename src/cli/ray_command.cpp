// vri ray SCENE.json --pixel PX PY [--step H] -o RAY.csv [--plot RAY.svg]:
// the scalar signal along one pixel's ray and its 0th/1st/2nd-order
// approximations with their errors xi (see vri/analysis.hpp).
#include <array>
#include <cstdio>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <string>

#include "commands.hpp"
#include "vri/analysis.hpp"
#include "vri/error.hpp"
#include "vri/io.hpp"
#include "vri/scene.hpp"

namespace vri::cli {

namespace {

struct RayArgs {
  std::string scene, output;
  std::optional<std::string> plot;
  std::array<int, 2> pixel{};
  std::optional<double> step;
};

std::span<const std::byte> bytes_of(const std::string& s) { return std::as_bytes(std::span(s)); }

int run_ray(const RayArgs& args) {
  if (std::filesystem::path(args.output).extension() != ".csv") throw Error("output '" + args.output + "' must end in .csv");
  if (args.plot && std::filesystem::path(*args.plot).extension() != ".svg")
    throw Error("plot '" + *args.plot + "' must end in .svg");
  const Scene scene = load_scene(args.scene);
  const auto [px, py] = args.pixel;
  const RaySignal sig = pixel_signal(scene, px, py, args.step);

  const double xi[3] = {sig.xi(0), sig.xi(1), sig.xi(2)};
  std::ostringstream csv;
  csv.precision(10);
  csv << "# vri ray: pixel " << px << " " << py << ", "
      << (args.step ? "step " + format_g(*args.step) + " voxel units" : std::string("cell faces + midpoints"))
      << "\n# xi0 = " << xi[0] << ", xi1 = " << xi[1] << ", xi2 = " << xi[2] << "\n"
      << "t,signal,order0,order1,order2,is_sample\n";
  for (const RaySignalRow& r : signal_rows(sig))
    csv << r.t << "," << r.signal << "," << r.order[0] << "," << r.order[1] << "," << r.order[2] << ","
        << (r.is_sample ? 1 : 0) << "\n";
  const std::string svg = args.plot ? ray_signal_svg(sig) : std::string();
  write_file_atomically(args.output, bytes_of(csv.str()));
  if (args.plot) write_file_atomically(*args.plot, bytes_of(svg));
  std::printf("samples %zu  xi0 %.6g  xi1 %.6g  xi2 %.6g\n", sig.sample_t().size(), xi[0], xi[1], xi[2]);
  return 0;
}

}  // namespace

Runner add_ray_command(CLI::App& app) {
  auto args = std::make_shared<RayArgs>();
  CLI::App* cmd = app.add_subcommand("ray", "The scalar signal along one ray and its 0th/1st/2nd-order approximations");
  cmd->add_option("scene", args->scene, "Scene JSON file")->required();
  cmd->add_option("--pixel", args->pixel, "Pixel column and row")->required();
  cmd->add_option("--step", args->step, "Uniform sample step in voxel units (default: cell faces and midpoints)");
  cmd->add_option("-o,--output", args->output, "CSV output")->required();
  cmd->add_option("--plot", args->plot, "SVG plot output");
  return [args] { return run_ray(*args); };
}

}  // namespace vri::cli
