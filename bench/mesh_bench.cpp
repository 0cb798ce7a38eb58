// Rendering speed of the mesh methods on the bundled blunt fin (187,318
// tetrahedra, scenes/blunt_fin.json) at 256x256 and 512x512, and the table builds.
// Run: ./build/bench/bench_mesh --benchmark_min_time=1 (figures: docs/PERFORMANCE.md)
#include <benchmark/benchmark.h>

#include "vri/methods.hpp"
#include "methods/mesh_tables.hpp"
#include "methods/projected/projected_tetrahedra.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"
#include "tables/cylindrical_table.hpp"

namespace {

const vri::Scene& fin() {
  static const vri::Scene scene = vri::load_scene(VRI_SOURCE_DIR "/scenes/blunt_fin.json");
  return scene;
}

vri::Camera camera(int size) {
  vri::CameraSpec cs = fin().camera;
  cs.width = cs.height = size;
  return vri::Camera(cs);
}

const vri::SlabTable& table() {  // table_size 128, 64 lengths (the scene's)
  static const auto t = vri::make_slab_table(fin().method, fin().mesh(), fin().transfer_function);
  return *t;
}

void count_rays(benchmark::State& state, int size) {
  state.counters["Mrays/s"] =
      benchmark::Counter(double(size) * size * state.iterations() / 1e6, benchmark::Counter::kIsRate);
}

void BM_MeshExact(benchmark::State& state) {
  vri::MethodSpec spec = fin().method;
  const auto exact = vri::make_integrator(spec, fin().mesh(), fin().transfer_function);
  const vri::Camera cam = camera(int(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(vri::render(cam, *exact, {.threads = 2}).data().data());
  count_rays(state, int(state.range(0)));
}
BENCHMARK(BM_MeshExact)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_TetRaycast(benchmark::State& state) {
  vri::MethodSpec spec = fin().method;
  spec.name = "tet-raycast";
  const auto raycast = vri::make_integrator(spec, fin().mesh(), fin().transfer_function);
  const vri::Camera cam = camera(int(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(vri::render(cam, *raycast, {.threads = 2}).data().data());
  count_rays(state, int(state.range(0)));
}
BENCHMARK(BM_TetRaycast)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Pt(benchmark::State& state) {
  const vri::Camera cam = camera(int(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(vri::render_projected(cam, fin().mesh(), table(), {.threads = 2}).data().data());
  count_rays(state, int(state.range(0)));
}
BENCHMARK(BM_Pt)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_PtCylindrical(benchmark::State& state) {
  const vri::CylindricalTable cyl(table(), 128, 128);
  const vri::Camera cam = camera(int(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(vri::render_projected(cam, fin().mesh(), cyl, {.threads = 2}).data().data());
  count_rays(state, int(state.range(0)));
}
BENCHMARK(BM_PtCylindrical)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime();

// args: table size N, lengths M, builder (0 incremental: O(M N^2); 1 brute: O(M N^3)), on 2 threads.
void BM_SlabTable(benchmark::State& state) {
  vri::MethodSpec spec = fin().method;
  spec.table_size = int(state.range(0));
  spec.length_samples = int(state.range(1));
  spec.builder = state.range(2) ? "brute" : "incremental";
  state.SetLabel(spec.builder);
  for (auto _ : state) benchmark::DoNotOptimize(vri::make_slab_table(spec, fin().mesh(), fin().transfer_function));
}
BENCHMARK(BM_SlabTable)
    ->Args({64, 32, 1})->Args({64, 32, 0})->Args({128, 64, 0})->Args({256, 64, 0})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_CylindricalResample(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(vri::CylindricalTable(table(), 128, int(state.range(0))));
}
BENCHMARK(BM_CylindricalResample)->Arg(128)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
