// Speed of the adaptive methods (Campagnolo et al. 2015 coupled/decoupled and
// vri's guaranteed mode) against riemann at h = 0.1 on the bonsai scene at
// 200 x 150 pixels. Run: ./build/bench/bench_adaptive --benchmark_min_time=1 --benchmark_repetitions=3
// (figures: docs/ADAPTIVE.md).
#include <benchmark/benchmark.h>

#include <cmath>

#include "methods/adaptive/adaptive_guaranteed.hpp"
#include "methods/adaptive/adaptive_simpson.hpp"
#include "methods/riemann/riemann.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace {

const vri::Scene& bonsai() {
  static const vri::Scene scene = vri::load_scene(VRI_SOURCE_DIR "/scenes/bonsai.json");
  return scene;
}

void render_with(benchmark::State& state, const vri::Integrator& integrator) {
  vri::CameraSpec spec = bonsai().camera;
  spec.width = 200;
  spec.height = 150;
  const vri::Camera cam(spec);
  for (auto _ : state) {
    vri::Image img = vri::render(cam, integrator, {.threads = 1});
    benchmark::DoNotOptimize(img.data().data());
  }
  state.counters["rays/s"] = benchmark::Counter(double(cam.width()) * cam.height() * state.iterations(),
                                                benchmark::Counter::kIsRate);
}

void BM_Riemann(benchmark::State& state) {
  render_with(state, vri::RiemannIntegrator(bonsai().grid(), bonsai().transfer_function, 0.1));
}
BENCHMARK(BM_Riemann)->Unit(benchmark::kMillisecond)->UseRealTime();

// args: strategy (0 coupled, 1 decoupled, 2 guaranteed), -log10(tolerance)
void BM_Adaptive(benchmark::State& state) {
  const vri::AdaptiveParams p{.tolerance = std::pow(10.0, -double(state.range(1))),
                              .strategy = vri::AdaptiveStrategy(state.range(0))};
  if (p.strategy == vri::AdaptiveStrategy::Guaranteed)
    render_with(state, vri::GuaranteedAdaptiveIntegrator(bonsai().grid(), bonsai().transfer_function, p));
  else
    render_with(state, vri::AdaptiveSimpsonIntegrator(bonsai().grid(), bonsai().transfer_function, p));
}
BENCHMARK(BM_Adaptive)->ArgsProduct({{0, 1, 2}, {2, 3}})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
