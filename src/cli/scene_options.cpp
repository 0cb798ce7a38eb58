#include "scene_options.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "vri/error.hpp"
#include "vri/methods.hpp"

namespace vri::cli {

Vec3 parse_background(const std::string& text) {
  double v[3];
  char tail = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &tail) != 3 ||
      !std::all_of(v, v + 3, [](double x) { return x >= 0 && x <= 1; }))
    throw Error("--background must be 'none' or three numbers in [0, 1] such as 0.1,0.1,0.2, not '" + text + "'");
  return {v[0], v[1], v[2]};
}

void SceneFlags::add_to(CLI::App* cmd) {
  SceneOverrides& o = overrides;
  cmd->add_option("--background", background,
                  "PNG: 'none' keeps alpha (straight colour, no background); or R,G,B in [0, 1] over the scene's");
  cmd->add_option("--method", o.method, "Integration method (overrides the scene): " + method_names(nullptr, "or"));
  cmd->add_option("--step", o.step, "Step size in voxel units");
  cmd->add_option("--tolerance", o.tolerance, "Error tolerance (exact, adaptive)");
  cmd->add_option("--table-size", o.table_size, "Pre-integration table size");
  cmd->add_option("--iterations", o.iterations, "preint2*: parabola chords per table entry (1..4096; default 8)");
  cmd->add_option("--termination", o.termination,
                  "riemann, preint1, preint2, preint2-dual: stop a ray once its transmittance is below this (0: off)");
  cmd->add_flag("--no-skip", no_skip,
                "riemann, preint1, preint2, preint2-dual, adaptive: march through empty space too (the plain path; "
                "adaptive coupled/decoupled: the paper's algorithm as written, without the early stop)");
  cmd->add_flag("--double", double_math,
                "riemann, preint1, preint2, preint2-dual: sample, look up and composite in double (the reference of "
                "their float paths)");
  // The scene's range for the seed (0 .. 2^53), checked on the text: a
  // negative number would wrap to a huge unsigned one (issue 47).
  cmd->add_option("--jitter", o.jitter,
                  "riemann: move each pixel's samples by a seeded random share of a step (against wood-grain rings)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            std::size_t used = 0;
            long long seed = -1;
            try {
              seed = std::stoll(text, &used);
            } catch (const std::exception&) {
            }
            if (used != text.size() || seed < 0 || seed > (1LL << 53))
              return "expected an integer seed in [0, 2^53], found '" + text + "'";
            return "";
          },
          "SEED"));
  cmd->add_option("--width", o.width, "Image width in pixels");
  cmd->add_option("--height", o.height, "Image height in pixels");
  cmd->add_flag("--fit", fit, "Frame the volume's box (as ParaView's reset camera), then apply the motions");
  cmd->add_option("--azimuth", o.azimuth, "Turn the eye about the up vector (degrees, VTK's Azimuth)");
  cmd->add_option("--elevation", o.elevation, "Raise the eye towards the up vector (degrees)");
  cmd->add_option("--roll", o.roll, "Turn the up vector about the view direction (degrees)");
  cmd->add_option("--zoom", o.zoom, "Magnify by this factor (VTK's Zoom: narrows the field of view)");
  cmd->add_option("--threads", threads, "Worker threads (0: all cores; at most 1024)");
  cmd->add_option("--backend", backend, "cpu (default) or vulkan: render on a Vulkan device (`vri devices`)");
  cmd->add_option("--max-samples", o.max_samples, "Cap on samples per ray (default 1e7; scene method.max_samples)");
  cmd->add_option("--max-work", o.max_work, "Cap on samples per ray x pixels (default 2e10; scene method.max_work)");
  cmd->add_option("--h0", o.h0, "adaptive: initial step (voxel units)");
  cmd->add_option("--hmin", o.hmin, "adaptive: smallest step (voxel units)");
  cmd->add_option("--hmax", o.hmax, "adaptive: largest step (voxel units)");
  cmd->add_option("--strategy", o.strategy, "adaptive: coupled, decoupled or guaranteed");
  cmd->add_option("--colormap", look.colormap,
                  "A volume file in place of the scene: this colour map (viridis, magma, inferno, plasma, cividis, "
                  "grayscale, cool_to_warm, rainbow_uniform) instead of the suggested transfer function");
  cmd->add_option("--opacity", look.opacity, "A volume file: the opacity over the range, ramp or sigmoid");
  cmd->add_option("--range", look.range, "A volume file: the transfer function's range, data, pLO,pHI "
                                         "(percentiles, such as p1,p99) or LO,HI");
}

Scene SceneFlags::load(const std::string& scene_file, const PartialLoad* part) const {
  const bool volume_file = is_volume_file(scene_file);
  const bool looked = !look.colormap.empty() || !look.opacity.empty() || !look.range.empty();
  if (looked && !volume_file)
    throw Error("--colormap, --opacity and --range apply to a volume file; a scene sets its \"transfer_function\"");
  if (volume_file && part)
    throw Error("a volume file renders in one process; --distributed and mpirun need a scene naming it");
  Scene scene = volume_file ? volume_scene(load_volume(scene_file), look)
                : part      ? load_scene(scene_file, *part)
                            : load_scene(scene_file);
  SceneOverrides o = overrides;
  if (no_skip) o.skip_empty = false;
  if (double_math) o.float_math = false;
  if (fit) o.fit = true;
  apply_overrides(scene, o);
  if (!background.empty() && background != "none") scene.background = parse_background(background);
  return scene;
}

}  // namespace vri::cli
