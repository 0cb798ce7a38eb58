// Interpolated lighting for preint1 (docs/PERFORMANCE.md, "Pre-integration tables").
//   BM_Tables/<kind>/N/threads   the unweighted incremental table, or the two
//                                packed weighted tables (four weighted
//                                integrals, Lum et al. 2004 §4.3), N x N,
//                                presets/bonsai.json, slabs of one voxel
//   BM_Render/<mode>/threads     scenes/neghip_lit.json at 128 x 128, step 1,
//                                table 256: unlit, sampled, interpolated
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include "vri/methods.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"
#include "tables/incremental_builder.hpp"
#include "tables/weighted_tables.hpp"

namespace {

const vri::TransferFunction& bench_tf() {
  static const vri::TransferFunction tf = vri::load_transfer_function(VRI_SOURCE_DIR "/presets/bonsai.json");
  return tf;
}

void BM_Tables(benchmark::State& state, bool weighted) {
  const vri::DiscreteTf tf(bench_tf(), static_cast<int>(state.range(0)));
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(1));
  for (auto _ : state) {
    if (weighted)
      benchmark::DoNotOptimize(vri::build_weighted_tables(tf, 1.0).back.data().data());
    else
      benchmark::DoNotOptimize(vri::IncrementalBuilder().build(tf, 1.0).data().data());
  }
}

// The render alone: the integrator (and its tables) is built once, outside the loop.
void BM_Render(benchmark::State& state, const char* mode) {
  static const vri::Scene scene = [] {
    vri::Scene s = vri::load_scene(VRI_SOURCE_DIR "/scenes/neghip_lit.json");
    s.camera.width = s.camera.height = 128;
    return s;
  }();
  vri::Lighting lighting = scene.lighting;
  lighting.enabled = std::string(mode) != "unlit";
  if (lighting.enabled) lighting.mode = mode;
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(0));
  const auto integrator = vri::make_integrator({.name = "preint1", .step = 1.0}, scene.grid(), scene.transfer_function, lighting);
  const vri::Camera camera(scene.camera);
  for (auto _ : state) benchmark::DoNotOptimize(vri::render(camera, *integrator).data().data());
}

BENCHMARK_CAPTURE(BM_Tables, incremental, false)->ArgsProduct({{256, 1024}, {1, 2}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Tables, weighted, true)->ArgsProduct({{256, 1024}, {1, 2}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Render, unlit, "unlit")->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Render, sampled, "sampled")->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Render, interpolated, "interpolated")->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
