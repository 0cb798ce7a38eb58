// vri render SCENE.json -o OUT.(npy|png) [--method NAME] [--step H]
//   [--tolerance E] [--table-size N] [--width W --height H] [--threads K]
//   [--h0 H --hmin H --hmax H --strategy S] [--error-estimate ERR.npy]
//   [--trace-pixel PX PY --trace STEPS.csv] [--termination T] [--no-skip] [--double]
//   [--distributed] (under mpirun: render_distributed.hpp)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "io/exr_output.hpp"
#include "progress_bar.hpp"
#include "render_distributed.hpp"
#include "scene_options.hpp"
#include "vri/error.hpp"
#include "vri/methods.hpp"
#include "vri/io.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace vri::cli {

namespace {

struct RenderArgs {
  std::string scene, output;
  SceneFlags flags;
  bool quiet = false, distributed = false;
  int png_bits = 8;
  std::optional<std::string> error_estimate, trace;
  std::vector<int> trace_pixel;
};

// The accepted steps along one pixel's ray as CSV (t and h in voxel units).
std::string trace_csv(const Ray& ray, const ErrorEstimatingIntegrator& integrator, double voxel_unit) {
  RayStats stats;
  stats.record_steps = true;
  integrator.integrate(ray, stats);
  std::ostringstream csv;
  csv.precision(10);
  csv << "integral,t,h,alpha\n";
  for (const AdaptiveStep& s : stats.steps)
    csv << (s.outer ? "outer" : "inner") << ',' << s.t / voxel_unit << ',' << s.h / voxel_unit << ',' << s.alpha
        << '\n';
  return csv.str();
}

int run_render(const RenderArgs& args) {
  const std::filesystem::path out(args.output);
  const std::string ext = out.extension().string();
  if (ext != ".npy" && ext != ".png" && ext != ".exr")
    throw Error("output '" + args.output + "' must end in .npy, .png or .exr");
  if (ext == ".exr" && !exr_supported()) write_exr(out, Image());  // says why, before any work
  if (args.png_bits != 8 && args.png_bits != 16) throw Error("--png-bits must be 8 or 16");
  if ((args.png_bits != 8 || args.flags.background == "none") && ext != ".png")
    throw Error("--png-bits and --background none apply to .png output");
  PngFormat png{.transparent = args.flags.background == "none", .bits = args.png_bits};
  const int threads = checked_threads(args.flags.threads);
  // Each output is staged as soon as it exists; main() commits them together.
  const auto write_image = [&](const Image& image, const Scene& scene) {
    if (ext == ".npy") write_npy(out, image);
    else if (ext == ".exr") write_exr(out, image);
    else write_png(out, image, scene.background, png);
  };
  if (args.distributed || launched_by_mpirun()) {
    if (args.error_estimate || args.trace) throw Error("--error-estimate and --trace are not distributed");
    return run_render_distributed({args.scene, args.output, args.flags, threads, write_image});
  }

  const Scene scene = args.flags.load(args.scene);
  if (args.error_estimate && std::filesystem::path(*args.error_estimate).extension() != ".npy")
    throw Error("--error-estimate '" + *args.error_estimate + "' must end in .npy");
  if (args.trace.has_value() != !args.trace_pixel.empty()) throw Error("--trace and --trace-pixel go together");
  if (args.trace && std::filesystem::path(*args.trace).extension() != ".csv")
    throw Error("--trace '" + *args.trace + "' must end in .csv");

  // Every check comes before the first file is written.
  const SceneRenderer renderer(scene, args.flags.parsed_backend(), threads);
  const Camera& camera = renderer.camera();
  const ErrorEstimatingIntegrator* estimating =
      args.error_estimate || args.trace ? &renderer.error_estimating(args.error_estimate ? "--error-estimate" : "--trace")
                                        : nullptr;
  if (args.trace) {
    const int px = args.trace_pixel[0], py = args.trace_pixel[1];
    if (px < 0 || py < 0 || px >= camera.width() || py >= camera.height())
      throw Error("--trace-pixel " + std::to_string(px) + " " + std::to_string(py) + " lies outside the image");
  }
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();  // process CPU time, all threads
  ProgressBar progress(!args.quiet);
  const Image image = renderer.render({.threads = threads, .progress = std::ref(progress)});
  progress.finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  write_image(image, scene);
  if (args.error_estimate) write_npy(*args.error_estimate, renderer.render_error_estimate({.threads = threads}));
  if (args.trace) {
    const std::string trace =
        trace_csv(camera.ray(args.trace_pixel[0], args.trace_pixel[1]), *estimating, scene.grid().voxel_unit());
    write_file_atomically(*args.trace, std::as_bytes(std::span(trace.data(), trace.size())));
  }
  if (const auto cause = transparency_cause(image, scene, camera))
    std::cerr << "vri: warning: every pixel is transparent: " << *cause << "\n";
  std::cerr << "vri: rendered " << camera.width() << "x" << camera.height() << " with '" << renderer.method_name()
            << "' in " << seconds << " s (CPU " << cpu_seconds << " s) -> " << args.output
            << (renderer.backend() == Backend::Vulkan ? " (on " + renderer.device_name() + ")" : "") << "\n";
  if (const double eps = scene.method.fast.termination; eps > 0) {
    const TerminationBound bound = termination_bound(image, eps);
    std::cerr << "vri: early termination below transmittance " << eps << ": " << bound.pixels
              << " pixels may have stopped early; each dropped at most " << bound.max_remaining
              << " (their remaining transmittance) times its largest colour\n";
  }
  return 0;
}

}  // namespace

Runner add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene to .npy (float RGBA) or .png");
  cmd->add_option("scene", args->scene, "Scene JSON file, or a volume file (seen as --colormap, --opacity and --range say)")->required();
  cmd->add_option("-o,--output", args->output, "Output image (.npy, .png or .exr)")->required();
  args->flags.add_to(cmd);
  cmd->add_option("--png-bits", args->png_bits, "PNG: 8 (default) or 16 bits a channel");
  cmd->add_flag("--distributed", args->distributed,
                "Sort-last over the ranks of mpirun (the default when mpirun starts several): rank 0 writes");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress line (it shows only on a terminal, after a second)");
  cmd->add_option("--error-estimate", args->error_estimate, "adaptive: write the per-pixel error estimate (.npy)");
  cmd->add_option("--trace-pixel", args->trace_pixel, "adaptive: pixel PX PY whose steps --trace writes")
      ->expected(2);
  cmd->add_option("--trace", args->trace, "adaptive: write the steps along one ray (.csv)");
  return [args] { return run_render(*args); };
}

}  // namespace vri::cli
