// Rendering time of the first- and second-order pre-integrated methods side
// by side (docs/SECOND_ORDER.md, "Results"; El Hajjar et al. 2008 Figures 7-9):
// neghip, fuel and bucky at 512x512 on one thread, tables built outside the
// timed loop, process CPU time (steadier than wall time on a shared machine).
//   BM_PreintRender/<scene>/<method>   method: 0 preint1@a, 1 preint1@1,
//       2 preint2@a, 3 preint2-dual, 4 preint2@a with a 64^3 table (4 MiB,
//       cache-resident; 256^3 is 256 MiB), 5 preint1@a on its float path,
//       6 and 7 preint2@a on its float path (tables of 256^3 and 64^3),
//       with a = 2 (bucky: 4) as in the paper. All skip empty space; 0 to 4
//       run the double paths, so the orders compare like for like; 5 to 7
//       the float paths, what unlit preint1 and preint2 do by default.
// Run: ./build/bench/bench_preint_render --benchmark_repetitions=5
//      --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <array>
#include <memory>
#include <string>

#include "vri/methods.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace {

const std::array<const char*, 3> kScenes = {"neghip", "fuel", "bucky"};

const vri::Scene& scene(int index) {
  static const std::array<vri::Scene, 3> scenes = {
      vri::load_scene(VRI_SOURCE_DIR "/scenes/neghip.json"), vri::load_scene(VRI_SOURCE_DIR "/scenes/fuel.json"),
      vri::load_scene(VRI_SOURCE_DIR "/scenes/bucky.json")};
  return scenes[index];
}

vri::MethodSpec method(int scene_index, int index) {
  const double a = scene_index == 2 ? 4 : 2;  // bucky: steps 4 and 1 (the paper's Figure 9)
  switch (index) {
    case 0: return {.name = "preint1", .step = a, .fast = {.float_math = false}};
    case 1: return {.name = "preint1", .step = 1, .fast = {.float_math = false}};
    case 5: return {.name = "preint1", .step = a};
    case 2: return {.name = "preint2", .step = a, .fast = {.float_math = false}};
    case 4:
      return {.name = "preint2", .step = a, .table_size = 64, .table_size_given = true, .fast = {.float_math = false}};
    case 6: return {.name = "preint2", .step = a};
    case 7: return {.name = "preint2", .step = a, .table_size = 64, .table_size_given = true};
    default: return {.name = "preint2-dual"};
  }
}

void BM_PreintRender(benchmark::State& state) {
  const int s = int(state.range(0)), m = int(state.range(1));
  const vri::Scene& sc = scene(s);
  const vri::MethodSpec spec = method(s, m);
  const auto integrator = vri::make_integrator(spec, sc.grid(), sc.transfer_function);
  vri::CameraSpec camera = sc.camera;
  camera.width = camera.height = 512;
  const vri::Camera cam(camera);
  for (auto _ : state) {
    vri::Image img = vri::render(cam, *integrator, {.threads = 1});
    benchmark::DoNotOptimize(img.data().data());
  }
  std::string label = kScenes[s];  // built by appends: GCC 12 warns (-Wrestrict) on a chain of +
  label.append(" ").append(spec.name);
  if (m != 3) label.append("@").append(std::to_string(int(spec.step)));
  if (m == 4 || m == 7) label.append(" N=64");
  if (m >= 5) label.append(" float");
  state.SetLabel(label);
}
BENCHMARK(BM_PreintRender)
    ->ArgsProduct({{0, 1, 2}, {0, 1, 2, 3, 4, 5, 6, 7}})
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
