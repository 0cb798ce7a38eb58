// vri render SCENE.json -o OUT.(npy|png) [--method NAME] [--step H]
//   [--tolerance E] [--table-size N] [--width W --height H] [--threads K]
//   [--h0 H --hmin H --hmax H --strategy S] [--error-estimate ERR.npy]
//   [--trace-pixel PX PY --trace STEPS.csv] [--termination T] [--no-skip] [--double]
#include <chrono>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "commands.hpp"
#include "render_checks.hpp"
#include "vri/core/error.hpp"
#include "vri/integrators/error_estimating_integrator.hpp"
#include "vri/integrators/make_integrator.hpp"
#include "vri/io/file_io.hpp"
#include "vri/io/npy.hpp"
#include "vri/io/png.hpp"
#include "vri/projected/projected_tetrahedra.hpp"
#include "vri/render/error_estimate.hpp"
#include "vri/render/renderer.hpp"
#include "vri/scene/scene.hpp"

namespace vri::cli {

namespace {

struct RenderArgs {
  std::string scene, output;
  std::optional<std::string> method;
  std::optional<double> step, tolerance, termination, max_samples, max_work;
  bool no_skip = false, double_math = false;
  std::optional<int> table_size, iterations, width, height;
  int threads = 0;
  std::optional<double> h0, hmin, hmax;
  std::optional<std::string> strategy, error_estimate, trace;
  std::vector<int> trace_pixel;
};

const ErrorEstimatingIntegrator& error_estimating(const Integrator& integrator, const char* flag) {
  const auto* e = dynamic_cast<const ErrorEstimatingIntegrator*>(&integrator);
  if (!e) throw Error(std::string(flag) + " needs method 'adaptive', not '" + std::string(integrator.name()) + "'");
  return *e;
}

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
  if (ext != ".npy" && ext != ".png")
    throw Error("output '" + args.output + "' must end in .npy or .png");
  const int threads = checked_threads(args.threads);

  Scene scene = load_scene(args.scene);
  if (args.method && *args.method != scene.method.name) {
    // The scene's table_size was chosen for its own method: preint2-dual,
    // named here instead, keeps its own default unless --table-size is given.
    scene.method.name = *args.method;
    scene.method.table_size_given = false;
  }
  if (args.step) scene.method.step = *args.step;
  if (args.tolerance) scene.method.tolerance = *args.tolerance;
  if (args.table_size) {
    scene.method.table_size = *args.table_size;
    scene.method.table_size_given = true;
  }
  if (args.iterations) scene.method.iterations = *args.iterations;
  if (args.width) scene.camera.width = *args.width;
  if (args.height) scene.camera.height = *args.height;
  if (args.h0) scene.method.h0 = *args.h0;
  if (args.hmin) scene.method.hmin = *args.hmin;
  if (args.hmax) scene.method.hmax = *args.hmax;
  if (args.strategy) scene.method.strategy = *args.strategy;
  if (args.termination) scene.method.fast.termination = *args.termination;
  if (args.no_skip) scene.method.fast.skip_empty = false;
  if (args.double_math) scene.method.fast.float_math = false;
  if (args.max_samples) scene.method.max_samples = *args.max_samples;
  if (args.max_work) scene.method.max_work = *args.max_work;
  check_method_parameters(scene.method);
  if (args.error_estimate && std::filesystem::path(*args.error_estimate).extension() != ".npy")
    throw Error("--error-estimate '" + *args.error_estimate + "' must end in .npy");
  if (args.trace.has_value() != !args.trace_pixel.empty()) throw Error("--trace and --trace-pixel go together");

  const Camera camera(scene.camera);
  check_work(scene, camera);  // before any table is built
  // `pt` and `pt-cylindrical` project whole tetrahedra; every other method integrates ray by ray.
  const std::string& name = scene.method.name;
  const bool projected = name == "pt" || name == "pt-cylindrical";
  std::unique_ptr<Integrator> integrator;
  std::unique_ptr<SlabTable> table;
  std::unique_ptr<WeightedLengthTables> weighted;  // lighting mode interpolated
  std::optional<CylindricalTable> cylinder;
  std::optional<WeightedCylindricalTables> weighted_cylinder;
  if (projected) {
    if (scene.method.fast.termination != 0)
      throw Error(name + ": early ray termination is not supported yet; it works in riemann, preint1 and preint2");
    table = make_slab_table(scene.method, scene.mesh(), scene.transfer_function);
    weighted = make_weighted_length_tables(scene.method, scene.mesh(), scene.transfer_function, scene.lighting);
    if (name == "pt-cylindrical") {
      const int size = scene.method.table_size, planes = scene.method.planes > 0 ? scene.method.planes : size;
      cylinder.emplace(*table, scene.transfer_function, size, planes);
      if (weighted)
        weighted_cylinder.emplace(CylindricalTable(weighted->front, scene.transfer_function, size, planes),
                                  CylindricalTable(weighted->back, scene.transfer_function, size, planes));
    }
  } else {
    integrator = std::visit(
        [&](const auto& volume) {
          return make_integrator(scene.method, volume, scene.transfer_function, scene.lighting);
        },
        scene.volume);
  }
  // Every check comes before the first file is written.
  const ErrorEstimatingIntegrator* estimating = nullptr;
  if (args.error_estimate || args.trace) {
    const char* flag = args.error_estimate ? "--error-estimate" : "--trace";
    if (!integrator) throw Error(std::string(flag) + " needs method 'adaptive', not '" + name + "'");
    estimating = &error_estimating(*integrator, flag);
  }
  if (args.trace) {
    const int px = args.trace_pixel[0], py = args.trace_pixel[1];
    if (px < 0 || py < 0 || px >= camera.width() || py >= camera.height())
      throw Error("--trace-pixel " + std::to_string(px) + " " + std::to_string(py) + " lies outside the image");
  }
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();  // process CPU time, all threads
  const RenderOptions options{.threads = threads};
  const Image image = cylinder   ? render_projected(camera, scene.mesh(), *cylinder, options, scene.lighting,
                                                   weighted_cylinder ? &*weighted_cylinder : nullptr)
                      : projected ? render_projected(camera, scene.mesh(), *table, options, scene.lighting, weighted.get())
                                  : render(camera, *integrator, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  // Each output is staged as soon as it exists; main() commits them together.
  refuse_non_finite(image, "the rendered image");
  if (ext == ".npy") write_npy(out, image);
  else write_png(out, image, scene.background);
  if (args.error_estimate) {
    const Image estimate = render_error_estimate(camera, *estimating, {.threads = threads});
    refuse_non_finite(estimate, "the error estimate");
    write_npy(*args.error_estimate, estimate);
  }
  std::string trace;
  if (args.trace)
    trace = trace_csv(camera.ray(args.trace_pixel[0], args.trace_pixel[1]), *estimating, scene.grid().voxel_unit());
  if (args.trace) write_file_atomically(*args.trace, std::as_bytes(std::span(trace.data(), trace.size())));
  warn_if_transparent(image, scene, camera);
  std::cerr << "vri: rendered " << camera.width() << "x" << camera.height() << " with '"
            << (projected ? name : std::string(integrator->name()))
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
  cmd->add_option("-o,--output", args->output, "Output image (.npy or .png)")->required();
  cmd->add_option("--method", args->method, "Integration method (overrides the scene)");
  cmd->add_option("--step", args->step, "Step size in voxel units");
  cmd->add_option("--tolerance", args->tolerance, "Error tolerance (exact, adaptive)");
  cmd->add_option("--table-size", args->table_size, "Pre-integration table size");
  cmd->add_option("--iterations", args->iterations, "preint2*: parabola steps per table entry (1..4096)");
  cmd->add_option("--termination", args->termination,
                  "riemann, preint1, preint2: stop a ray once its transmittance is below this (0: off)");
  cmd->add_flag("--no-skip", args->no_skip,
                "riemann, preint1, preint2: march through empty space too (the plain path)");
  cmd->add_flag("--double", args->double_math, "riemann, preint1, preint2: sample, look up and composite in double (the reference of their float paths)");
  cmd->add_option("--width", args->width, "Image width in pixels");
  cmd->add_option("--height", args->height, "Image height in pixels");
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores; at most 1024)");
  cmd->add_option("--max-samples", args->max_samples, "Cap on samples per ray (default 1e7; scene method.max_samples)");
  cmd->add_option("--max-work", args->max_work, "Cap on samples per ray x pixels (default 2e10; scene method.max_work)");
  cmd->add_option("--h0", args->h0, "adaptive: initial step (voxel units)");
  cmd->add_option("--hmin", args->hmin, "adaptive: smallest step (voxel units)");
  cmd->add_option("--hmax", args->hmax, "adaptive: largest step (voxel units)");
  cmd->add_option("--strategy", args->strategy, "adaptive: coupled, decoupled or guaranteed");
  cmd->add_option("--error-estimate", args->error_estimate, "adaptive: write the per-pixel error estimate (.npy)");
  cmd->add_option("--trace-pixel", args->trace_pixel, "adaptive: pixel PX PY whose steps --trace writes")
      ->expected(2);
  cmd->add_option("--trace", args->trace, "adaptive: write the steps along one ray (.csv)");
  return [args] { return run_render(*args); };
}

}  // namespace vri::cli
