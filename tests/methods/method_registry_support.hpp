#pragma once
// For the registry's tests: a bundled grid and mesh scene, small, with a
// method of the registry; and the outcome of making its renderer.
#include <string>

#include "test_support.hpp"
#include "vri/error.hpp"
#include "vri/methods.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace vri::test {

inline Scene small_scene(bool grid, const MethodInfo& method) {
  Scene scene = load_scene(source_path(grid ? "scenes/neghip.json" : "scenes/blunt_fin.json"));
  scene.camera.width = 6;
  scene.camera.height = 5;
  scene.method.name = std::string(method.name);
  scene.method.table_size = 16;
  scene.method.table_size_given = true;
  scene.method.iterations = 4;
  scene.method.length_samples = 8;
  return scene;
}

// The error making (and using) the scene's renderer gave, or "" when it rendered.
inline std::string refusal(const Scene& scene, Backend backend = Backend::Cpu) {
  try {
    const SceneRenderer renderer(scene, backend);
    renderer.render(RenderOptions{.threads = 1});
    return "";
  } catch (const Error& e) {
    return e.what();
  }
}

}  // namespace vri::test
