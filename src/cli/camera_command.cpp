// vri camera SCENE.json [the flags of vri render]: prints the scene's camera
// as a scene file holds it (eye, target, up, fov_y, width, height,
// projection) after the size flags, "fit" and the motions are applied. So a
// fitted camera can be frozen into a scene, and other programs (the VTK
// side-by-side scripts) see exactly what vri renders through.
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "scene/scene_json.hpp"
#include "scene_options.hpp"
#include "vri/camera.hpp"

namespace vri::cli {

Runner add_camera_command(CLI::App& app) {
  struct Args {
    std::string scene;
    SceneFlags flags;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("camera", "Print a scene's camera (after --fit and the motions) as scene JSON");
  cmd->add_option("scene", args->scene, "Scene JSON file, or a volume file (seen as --colormap, --opacity and --range say)")->required();
  args->flags.add_to(cmd);
  return [args] {
    const Scene scene = args->flags.load(args->scene);
    const Camera checked(scene.camera);  // the camera a render would use, validated
    std::cout << camera_json(checked.spec()).dump(1) << "\n";
    return 0;
  };
}

}  // namespace vri::cli
