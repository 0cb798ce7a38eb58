// vri render SCENE.json -o OUT.(npy|png) [--method NAME] [--step H]
//   [--tolerance E] [--table-size N] [--width W --height H] [--threads K]
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "commands.hpp"
#include "vri/core/error.hpp"
#include "vri/integrators/make_integrator.hpp"
#include "vri/io/npy.hpp"
#include "vri/io/png.hpp"
#include "vri/render/renderer.hpp"
#include "vri/scene/scene.hpp"

namespace vri::cli {

namespace {

struct RenderArgs {
  std::string scene, output;
  std::optional<std::string> method;
  std::optional<double> step, tolerance;
  std::optional<int> table_size, width, height;
  int threads = 0;
};

int run_render(const RenderArgs& args) {
  const std::filesystem::path out(args.output);
  const std::string ext = out.extension().string();
  if (ext != ".npy" && ext != ".png")
    throw Error("output '" + args.output + "' must end in .npy or .png");
  if (args.threads < 0) throw Error("--threads must be >= 0");

  Scene scene = load_scene(args.scene);
  if (args.method) scene.method.name = *args.method;
  if (args.step) scene.method.step = *args.step;
  if (args.tolerance) scene.method.tolerance = *args.tolerance;
  if (args.table_size) scene.method.table_size = *args.table_size;
  if (args.width) scene.camera.width = *args.width;
  if (args.height) scene.camera.height = *args.height;

  const Camera camera(scene.camera);
  const auto integrator = make_integrator(scene.method, scene.volume, scene.transfer_function, scene.lighting);
  const auto start = std::chrono::steady_clock::now();
  const Image image = render(camera, *integrator, {.threads = args.threads});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (ext == ".npy") write_npy(out, image);
  else write_png(out, image, scene.background);
  std::cerr << "vri: rendered " << camera.width() << "x" << camera.height() << " with '" << integrator->name()
            << "' in " << seconds << " s -> " << args.output << "\n";
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
  cmd->add_option("--width", args->width, "Image width in pixels");
  cmd->add_option("--height", args->height, "Image height in pixels");
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores)");
  return [args] { return run_render(*args); };
}

}  // namespace vri::cli
