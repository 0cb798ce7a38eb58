// Second-order table build times (docs/PERFORMANCE.md, "Second-order tables";
// El Hajjar et al. 2008 report 165 s CPU / 2.74 s GPU for 256^3 at 64 iterations).
// The transfer function is presets/bonsai.json (the errors also
// presets/neghip_spike.json), slabs of one voxel. Figures: scripts/second_order_tables.sh.
//   BM_SecondOrder/<builder>/N/K/threads   N^3 table, K iterations
//   BM_SecondOrderWeighted/<builder>/N/K/threads   build_weighted: the table
//       and the two weighted ones of interpolated lighting (second_order_weighted.hpp)
//   BM_SecondOrderErrors/<preset>/N/K      max and RMS over the table (all
//       channels) of fast - plain and of half - float32 (fast), as counters
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "vri/scene.hpp"
#include "tables/half_second_order_table.hpp"
#include "tables/second_order_table.hpp"
#include "tables/second_order_weighted.hpp"

namespace {

vri::DiscreteTf bench_tf(int n, const char* preset = "bonsai") {
  const vri::TransferFunction tf =
      vri::load_transfer_function(std::string(VRI_SOURCE_DIR "/presets/") + preset + ".json");
  return vri::DiscreteTf(tf, n);
}

void BM_SecondOrder(benchmark::State& state, const char* builder_name) {
  const vri::DiscreteTf discrete = bench_tf(static_cast<int>(state.range(0)));
  const auto builder = vri::make_second_order_builder(builder_name);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(2));
  for (auto _ : state)
    benchmark::DoNotOptimize(builder->build(discrete, 1.0, static_cast<int>(state.range(1))).data());
}

// plain integrates every chord exactly on its own: one iteration each.
BENCHMARK_CAPTURE(BM_SecondOrder, plain, "plain")
    ->ArgsProduct({{128}, {8}, {1, 2}})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SecondOrder, fast, "fast")
    ->ArgsProduct({{64, 128, 256}, {8, 16, 64}, {1, 2}})
    ->Unit(benchmark::kMillisecond);

void BM_SecondOrderWeighted(benchmark::State& state, const char* builder_name) {
  const vri::DiscreteTf discrete = bench_tf(static_cast<int>(state.range(0)));
  const auto builder = vri::make_second_order_builder(builder_name);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(2));
  for (auto _ : state)
    benchmark::DoNotOptimize(builder->build_weighted(discrete, 1.0, static_cast<int>(state.range(1))).back.data());
}
BENCHMARK_CAPTURE(BM_SecondOrderWeighted, fast, "fast")
    ->ArgsProduct({{64, 128, 256}, {8, 64}, {1, 2}})
    ->Unit(benchmark::kMillisecond);

void BM_SecondOrderErrors(benchmark::State& state, const char* preset) {
  const int n = static_cast<int>(state.range(0)), k = static_cast<int>(state.range(1));
  const vri::DiscreteTf discrete = bench_tf(n, preset);
  for (auto _ : state) {
    const vri::SecondOrderTable plain = vri::make_second_order_builder("plain")->build(discrete, 1.0, k);
    const vri::SecondOrderTable fast = vri::make_second_order_builder("fast")->build(discrete, 1.0, k);
    const vri::HalfSecondOrderTable half(fast);
    double fast_max = 0, fast_sq = 0, half_max = 0, half_sq = 0;
    for (int f = 0; f < n; ++f)
      for (int m = 0; m < n; ++m)
        for (int b = 0; b < n; ++b) {
          const vri::Rgba h = half.entry(f, m, b);
          for (int c = 0; c < 4; ++c) {
            const double df = double(fast.entry(f, m, b)[c]) - plain.entry(f, m, b)[c];
            const double dh = h[c] - fast.entry(f, m, b)[c];
            fast_max = std::max(fast_max, std::abs(df)), fast_sq += df * df;
            half_max = std::max(half_max, std::abs(dh)), half_sq += dh * dh;
          }
        }
    const double count = 4.0 * n * n * n;
    state.counters["fast_max"] = fast_max;
    state.counters["fast_rms"] = std::sqrt(fast_sq / count);
    state.counters["half_max"] = half_max;
    state.counters["half_rms"] = std::sqrt(half_sq / count);
  }
}
// plain integrates every chord on its own: 128^3 at K = 8 takes a few seconds.
BENCHMARK_CAPTURE(BM_SecondOrderErrors, bonsai, "bonsai")
    ->Args({128, 8})
    ->Args({64, 64})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SecondOrderErrors, neghip_spike, "neghip_spike")
    ->Args({128, 8})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
