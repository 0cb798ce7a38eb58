// vri turntable SCENE.json --frames N -o DIR | OUT.mp4 [--degrees D] [--fps F]
//   [the flags of vri render] (issue 20, item 3; docs/SCENES.md "Turntables"):
// the scene seen from N cameras turned about its up vector (VTK's Azimuth by
// D / N degrees a frame, from the scene's own camera), each frame rendered by
// one SceneRenderer, so the volume is read and the tables are built once.
// Frames go to DIR/frame_0000.png ... or into an MP4 (video_writer.hpp); all
// are kept in memory (PNG or video bytes) and written at the end, so a failed
// or interrupted run writes nothing.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "progress_bar.hpp"
#include "scene_options.hpp"
#include "video_writer.hpp"
#include "vri/camera.hpp"
#include "vri/error.hpp"
#include "vri/io.hpp"
#include "vri/render.hpp"  // checked_threads

namespace vri::cli {

namespace {

struct TurntableArgs {
  std::string scene, output;
  SceneFlags flags;
  int frames = 0;
  double degrees = 360;
  int fps = 30;
  bool quiet = false;
};

// frame_0000.png, ..., with at least four digits.
std::string frame_name(int i, int frames) {
  const std::string number = std::to_string(i);
  const std::size_t digits = std::max<std::size_t>(4, std::to_string(frames - 1).size());
  return "frame_" + std::string(digits - number.size(), '0') + number + ".png";
}

int run_turntable(const TurntableArgs& args) {
  namespace fs = std::filesystem;
  if (args.frames < 1 || args.frames > 100000) throw Error("--frames must be 1..100000");
  if (!std::isfinite(args.degrees)) throw Error("--degrees must be a finite angle");
  const fs::path out(args.output);
  const bool video = out.extension() == ".mp4";
  if (!video && out.has_extension())
    throw Error("output '" + args.output + "' must be a folder (frames as PNG) or end in .mp4");
  if (!video && fs::exists(out) && !fs::is_directory(out))
    throw Error("output '" + args.output + "' exists and is not a folder");
  if (video && !video_supported()) VideoWriter(1, 1, args.fps);  // says why, before any work
  const bool transparent = args.flags.background == "none";
  if (transparent && video) throw Error("--background none applies to PNG frames, not to video");
  const int threads = checked_threads(args.flags.threads);

  const Scene scene = args.flags.load(args.scene);
  const SceneRenderer renderer(scene, args.flags.parsed_backend(), threads);  // the volume and tables, once
  std::unique_ptr<VideoWriter> writer;
  if (video) writer = std::make_unique<VideoWriter>(scene.camera.width, scene.camera.height, args.fps);
  std::vector<std::vector<std::byte>> pngs;

  const auto start = std::chrono::steady_clock::now();
  ProgressBar progress(!args.quiet);
  for (int i = 0; i < args.frames; ++i) {
    const Camera camera(move_camera(scene.camera, args.degrees * i / args.frames, 0, 0, 1));
    const Image image = renderer.render(
        camera, {.threads = threads, .progress = [&](double f) { progress((i + f) / args.frames); }});
    if (writer) writer->add(image, scene.background);
    else pngs.push_back(encode_png(image, scene.background, {.transparent = transparent}));
  }
  progress.finish();

  if (writer) {
    const std::vector<std::byte> bytes = writer->finish();
    write_file_atomically(out, bytes);
  } else {
    if (OutputTransaction* outputs = OutputTransaction::active()) outputs->create_directories(out);
    else fs::create_directories(out);
    for (int i = 0; i < args.frames; ++i) write_file_atomically(out / frame_name(i, args.frames), pngs[i]);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cerr << "vri: rendered " << args.frames << " frames of " << scene.camera.width << "x" << scene.camera.height
            << " with '" << renderer.method_name() << "' in " << seconds << " s ("
            << seconds / args.frames << " s a frame) -> " << args.output
            << (writer ? std::string(" (") + writer->codec() + ")" : std::string()) << "\n";
  return 0;
}

}  // namespace

Runner add_turntable_command(CLI::App& app) {
  auto args = std::make_shared<TurntableArgs>();
  CLI::App* cmd = app.add_subcommand(
      "turntable", "Render an orbit about the scene's up vector: PNG frames in a folder, or an .mp4 video");
  cmd->add_option("scene", args->scene, "Scene JSON file, or a volume file (seen as --colormap, --opacity and --range say)")->required();
  cmd->add_option("-o,--output", args->output, "A folder (frame_0000.png, ...) or a video (.mp4)")->required();
  cmd->add_option("--frames", args->frames, "Number of frames")->required();
  cmd->add_option("--degrees", args->degrees, "The whole turn (default 360: the last frame leads back to the first)");
  cmd->add_option("--fps", args->fps, "Video: frames a second (default 30)");
  args->flags.add_to(cmd);
  cmd->add_flag("-q,--quiet", args->quiet, "No progress line (it shows only on a terminal, after a second)");
  return [args] { return run_turntable(*args); };
}

}  // namespace vri::cli
