// Issue 17, item 6: every bundled scene gives the same bytes with 1, 2 and
// 64 threads, grid scenes with every grid method family, mesh scenes with
// exact, tet-raycast and pt. Images and tables are small.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "test_support.hpp"
#include "vri/integrators/make_integrator.hpp"
#include "vri/projected/projected_tetrahedra.hpp"
#include "vri/render/renderer.hpp"
#include "vri/scene/scene.hpp"

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
    const Camera camera(scene.camera);
    const bool grid = std::holds_alternative<GridVolume>(scene.volume);
    ++(grid ? grids : meshes);
    const std::vector<std::string> methods =
        grid ? std::vector<std::string>{"riemann", "preint1", "preint2", "preint2-dual", "adaptive", "exact"}
             : std::vector<std::string>{"exact", "tet-raycast", "pt"};
    for (const std::string& method : methods) {
      MethodSpec spec = scene.method;
      spec.name = method;
      spec.table_size = 16;
      spec.table_size_given = true;
      spec.iterations = 4;
      spec.length_samples = 8;
      const std::string what = path.filename().string() + " " + method;
      if (method == "pt") {
        const auto table = make_slab_table(spec, scene.mesh(), scene.transfer_function);
        const auto weighted = make_weighted_length_tables(spec, scene.mesh(), scene.transfer_function, scene.lighting);
        expect_same_with_any_thread_count(
            [&](const RenderOptions& o) {
              return render_projected(camera, scene.mesh(), *table, o, scene.lighting, weighted.get());
            },
            what);
        continue;
      }
      const auto integrator = std::visit(
          [&](const auto& v) { return make_integrator(spec, v, scene.transfer_function, scene.lighting); }, scene.volume);
      expect_same_with_any_thread_count([&](const RenderOptions& o) { return render(camera, *integrator, o); }, what);
    }
  }
  EXPECT_GE(grids, 10);
  EXPECT_GE(meshes, 1);
}

}  // namespace
}  // namespace vri
