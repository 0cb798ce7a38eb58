// vri render SCENE.json -o OUT.(npy|png) [--method NAME] [--step H]
//   [--tolerance E] [--table-size N] [--width W --height H] [--threads K]
//   [--h0 H --hmin H --hmax H --strategy S] [--error-estimate ERR.npy]
//   [--trace-pixel PX PY --trace STEPS.csv] [--termination T] [--no-skip] [--double]
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
#include "exr_output.hpp"
#include "progress_bar.hpp"
#include "vri/core/error.hpp"
#include "vri/integrators/error_estimating_integrator.hpp"
#include "vri/io/file_io.hpp"
#include "vri/io/npy.hpp"
#include "vri/io/png.hpp"
#include "vri/render/render_checks.hpp"
#include "vri/render/scene_renderer.hpp"
#include "vri/scene/scene.hpp"
#include "vri/scene/scene_overrides.hpp"

namespace vri::cli {

namespace {

struct RenderArgs {
  std::string scene, output;
  SceneOverrides overrides;
  bool no_skip = false, double_math = false, fit = false, quiet = false;
  std::string background;  // "none" (PNG with alpha) or "R,G,B"
  int png_bits = 8;
  int threads = 0;
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

// --background R,G,B: three numbers in [0, 1].
Vec3 parse_background(const std::string& text) {
  double v[3];
  char tail = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &tail) != 3 ||
      !std::all_of(v, v + 3, [](double x) { return x >= 0 && x <= 1; }))
    throw Error("--background must be 'none' or three numbers in [0, 1] such as 0.1,0.1,0.2, not '" + text + "'");
  return {v[0], v[1], v[2]};
}

int run_render(RenderArgs args) {
  const std::filesystem::path out(args.output);
  const std::string ext = out.extension().string();
  if (ext != ".npy" && ext != ".png" && ext != ".exr")
    throw Error("output '" + args.output + "' must end in .npy, .png or .exr");
  if (ext == ".exr" && !exr_supported()) write_exr(out, Image());  // says why, before any work
  if (args.png_bits != 8 && args.png_bits != 16) throw Error("--png-bits must be 8 or 16");
  if ((args.png_bits != 8 || args.background == "none") && ext != ".png")
    throw Error("--png-bits and --background none apply to .png output");
  PngFormat png{.transparent = args.background == "none", .bits = args.png_bits};
  const int threads = checked_threads(args.threads);

  Scene scene = load_scene(args.scene);
  if (args.no_skip) args.overrides.skip_empty = false;
  if (args.double_math) args.overrides.float_math = false;
  if (args.fit) args.overrides.fit = true;
  apply_overrides(scene, args.overrides);
  if (!args.background.empty() && args.background != "none") scene.background = parse_background(args.background);
  if (args.error_estimate && std::filesystem::path(*args.error_estimate).extension() != ".npy")
    throw Error("--error-estimate '" + *args.error_estimate + "' must end in .npy");
  if (args.trace.has_value() != !args.trace_pixel.empty()) throw Error("--trace and --trace-pixel go together");

  // Every check comes before the first file is written.
  const SceneRenderer renderer(scene);
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
  // Each output is staged as soon as it exists; main() commits them together.
  if (ext == ".npy") write_npy(out, image);
  else if (ext == ".exr") write_exr(out, image);
  else write_png(out, image, scene.background, png);
  if (args.error_estimate) write_npy(*args.error_estimate, renderer.render_error_estimate({.threads = threads}));
  if (args.trace) {
    const std::string trace =
        trace_csv(camera.ray(args.trace_pixel[0], args.trace_pixel[1]), *estimating, scene.grid().voxel_unit());
    write_file_atomically(*args.trace, std::as_bytes(std::span(trace.data(), trace.size())));
  }
  if (const auto cause = transparency_cause(image, scene, camera))
    std::cerr << "vri: warning: every pixel is transparent: " << *cause << "\n";
  std::cerr << "vri: rendered " << camera.width() << "x" << camera.height() << " with '" << renderer.method_name()
            << "' in " << seconds << " s (CPU " << cpu_seconds << " s) -> " << args.output << "\n";
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
  cmd->add_option("scene", args->scene, "Scene JSON file")->required();
  cmd->add_option("-o,--output", args->output, "Output image (.npy, .png or .exr)")->required();
  cmd->add_option("--background", args->background,
                  "PNG: 'none' keeps alpha (straight colour, no background); or R,G,B in [0, 1] over the scene's");
  cmd->add_option("--png-bits", args->png_bits, "PNG: 8 (default) or 16 bits a channel");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress line (it shows only on a terminal, after a second)");
  cmd->add_option("--method", args->overrides.method, "Integration method (overrides the scene)");
  cmd->add_option("--step", args->overrides.step, "Step size in voxel units");
  cmd->add_option("--tolerance", args->overrides.tolerance, "Error tolerance (exact, adaptive)");
  cmd->add_option("--table-size", args->overrides.table_size, "Pre-integration table size");
  cmd->add_option("--iterations", args->overrides.iterations, "preint2*: parabola chords per table entry (1..4096; default 8)");
  cmd->add_option("--termination", args->overrides.termination,
                  "riemann, preint1, preint2, preint2-dual: stop a ray once its transmittance is below this (0: off)");
  cmd->add_flag("--no-skip", args->no_skip,
                "riemann, preint1, preint2, preint2-dual: march through empty space too (the plain path)");
  cmd->add_flag("--double", args->double_math, "riemann, preint1, preint2, preint2-dual: sample, look up and composite in double (the reference of their float paths)");
  cmd->add_option("--width", args->overrides.width, "Image width in pixels");
  cmd->add_option("--height", args->overrides.height, "Image height in pixels");
  cmd->add_flag("--fit", args->fit, "Frame the volume's box (as ParaView's reset camera), then apply the motions");
  cmd->add_option("--azimuth", args->overrides.azimuth, "Turn the eye about the up vector (degrees, VTK's Azimuth)");
  cmd->add_option("--elevation", args->overrides.elevation, "Raise the eye towards the up vector (degrees)");
  cmd->add_option("--roll", args->overrides.roll, "Turn the up vector about the view direction (degrees)");
  cmd->add_option("--zoom", args->overrides.zoom, "Magnify by this factor (VTK's Zoom: narrows the field of view)");
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores; at most 1024)");
  cmd->add_option("--max-samples", args->overrides.max_samples, "Cap on samples per ray (default 1e7; scene method.max_samples)");
  cmd->add_option("--max-work", args->overrides.max_work, "Cap on samples per ray x pixels (default 2e10; scene method.max_work)");
  cmd->add_option("--h0", args->overrides.h0, "adaptive: initial step (voxel units)");
  cmd->add_option("--hmin", args->overrides.hmin, "adaptive: smallest step (voxel units)");
  cmd->add_option("--hmax", args->overrides.hmax, "adaptive: largest step (voxel units)");
  cmd->add_option("--strategy", args->overrides.strategy, "adaptive: coupled, decoupled or guaranteed");
  cmd->add_option("--error-estimate", args->error_estimate, "adaptive: write the per-pixel error estimate (.npy)");
  cmd->add_option("--trace-pixel", args->trace_pixel, "adaptive: pixel PX PY whose steps --trace writes")
      ->expected(2);
  cmd->add_option("--trace", args->trace, "adaptive: write the steps along one ray (.csv)");
  return [args] { return run_render(*args); };
}

}  // namespace vri::cli
