#pragma once
// The flags that change a scene before it is rendered, shared by the commands
// that render one (`vri render`, `vri turntable`, `vri camera`): the method
// and its parameters, the image size, the camera motions, the background,
// threads, and a volume file's look (SPEC §12).
#include <CLI/CLI.hpp>

#include <string>

#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace vri::cli {

struct SceneFlags {
  SceneOverrides overrides;
  VolumeLook look;  // --colormap, --opacity, --range: a volume file's transfer function
  bool no_skip = false, double_math = false, fit = false;
  std::string background;  // "none" (PNG with alpha) or "R,G,B"
  std::string backend = "cpu";  // --backend cpu|vulkan (SPEC §11)
  int threads = 0;

  // Registers every flag on `cmd`.
  void add_to(CLI::App* cmd);
  // The scene file (or a volume file, as volume_scene() sees it) with the
  // flags applied; the background unless "none". With `part`, one part of
  // a scene's grid (distributed rendering, scene.hpp).
  Scene load(const std::string& scene_file, const PartialLoad* part = nullptr) const;
  // --backend as a Backend; vri::Error for another name.
  Backend parsed_backend() const { return parse_backend(backend); }
};

// --background R,G,B: three numbers in [0, 1]; vri::Error otherwise.
Vec3 parse_background(const std::string& text);

}  // namespace vri::cli
