// Second-order table build times (docs/PERFORMANCE.md, "Second-order tables";
// El Hajjar et al. 2008 report 165 s CPU / 2.74 s GPU for 256^3 at 64 iterations).
// The transfer function is presets/bonsai.json, slabs of one voxel.
//   BM_SecondOrder/<builder>/N/K/threads   N^3 table, K iterations
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include "vri/scene/scene.hpp"
#include "vri/tables/second_order_table.hpp"

namespace {

void BM_SecondOrder(benchmark::State& state, const char* builder_name) {
  static const vri::TransferFunction tf = vri::load_transfer_function(VRI_SOURCE_DIR "/presets/bonsai.json");
  const vri::DiscreteTf discrete(tf, static_cast<int>(state.range(0)));
  const auto builder = vri::make_second_order_builder(builder_name);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(2));
  for (auto _ : state)
    benchmark::DoNotOptimize(builder->build(discrete, 1.0, static_cast<int>(state.range(1))).data());
}

// plain at 256^3 takes tens of seconds a run: one iteration each.
BENCHMARK_CAPTURE(BM_SecondOrder, plain, "plain")
    ->ArgsProduct({{256}, {64}, {1, 2}})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SecondOrder, fast, "fast")
    ->ArgsProduct({{64, 128, 256}, {64}, {1, 2}})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
