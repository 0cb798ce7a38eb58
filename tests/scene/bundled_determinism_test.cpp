// Issue 17, item 6: every bundled scene gives the same bytes with 1, 2 and
// 64 threads with every method that renders it (vri/methods.hpp). Images and
// tables are small.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "test_support.hpp"
#include "vri/methods.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace vri {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> bundled_scenes() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(test::source_path("scenes")))
    if (e.path().extension() == ".json") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// Renders with 1 thread, then expects the same floats with 2 and 64.
template <class RenderWith>
void expect_same_with_any_thread_count(RenderWith render_with, const std::string& what) {
  const Image one = render_with(RenderOptions{.threads = 1});
  for (int threads : {2, 64})
    EXPECT_EQ(test::pixels(render_with(RenderOptions{.threads = threads})), test::pixels(one)) << what << " threads " << threads;
}

TEST(BundledDeterminism, EveryBundledSceneEveryMethodFamily) {
  int grids = 0, meshes = 0;
  for (const fs::path& path : bundled_scenes()) {
    Scene scene = load_scene(path);
    scene.camera.width = 10;
    scene.camera.height = 7;
    const bool grid = std::holds_alternative<GridVolume>(scene.volume);
    ++(grid ? grids : meshes);
    for (const MethodInfo& method : methods()) {  // every method the registry says renders this kind
      if (!(grid ? method.grid : method.mesh)) continue;
      Scene s = scene;
      s.method.name = std::string(method.name);
      s.method.table_size = 16;
      s.method.table_size_given = true;
      s.method.iterations = 4;
      s.method.length_samples = 8;
      const SceneRenderer renderer(s);
      expect_same_with_any_thread_count([&](const RenderOptions& o) { return renderer.render(o); },
                                        path.filename().string() + " " + s.method.name);
    }
  }
  EXPECT_GE(grids, 10);
  EXPECT_GE(meshes, 1);
}

}  // namespace
}  // namespace vri
