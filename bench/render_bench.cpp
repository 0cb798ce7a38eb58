// Rendering speed of the foundation's methods on a bundled dataset at 512x512.
// Run: ./build/bench_render --benchmark_min_time=2 (figures: docs/PERFORMANCE.md)
#include <benchmark/benchmark.h>

#include <cmath>

#include "methods/exact/exact.hpp"
#include "methods/riemann/riemann.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace {

const vri::Scene& neghip() {
  static const vri::Scene scene = vri::load_scene(VRI_SOURCE_DIR "/scenes/neghip.json");
  return scene;
}

void render_with(benchmark::State& state, const vri::Integrator& integrator) {
  const vri::Camera cam(neghip().camera);  // 512 x 512
  for (auto _ : state) {
    vri::Image img = vri::render(cam, integrator, {.threads = int(state.range(0))});
    benchmark::DoNotOptimize(img.data().data());
  }
  state.counters["Mrays/s"] = benchmark::Counter(double(cam.width()) * cam.height() * state.iterations() / 1e6,
                                                 benchmark::Counter::kIsRate);
}

void BM_Riemann(benchmark::State& state) {
  const vri::RiemannIntegrator riemann(neghip().grid(), neghip().transfer_function, state.range(1) / 100.0);
  render_with(state, riemann);
}
// args: threads, step in hundredths of a voxel
BENCHMARK(BM_Riemann)->Args({1, 100})->Args({2, 100})->Args({2, 50})->Args({2, 10})->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Exact(benchmark::State& state) {
  const vri::ExactIntegrator exact(neghip().grid(), neghip().transfer_function, std::pow(10.0, -double(state.range(1))));
  render_with(state, exact);
}
// args: threads, -log10(tolerance)
BENCHMARK(BM_Exact)->Args({1, 4})->Args({2, 4})->Args({2, 6})->Args({2, 8})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
