// Empty-space skipping set-up times (docs/PERFORMANCE.md, "Transfer-function edits"),
// one thread:
//   BM_MacroCells/N          min/max macro cells of an N^3 volume (once per volume:
//                            compute_macro_ranges)
//   BM_Reclassify/N          after a transfer-function edit: ZeroOpacity of the
//                            discretised function (256 scalars) and EmptySpace over
//                            the (N/8)^3 macro cells
//   BM_TfEdit/N              the same plus the first-order table (n = 256,
//                            incremental builder): all a preint1 render redoes
//   BM_Preint1Setup/N        a preint1 integrator made for a new transfer
//                            function on a volume already rendered (the viewer's
//                            edit: make_integrator, one thread)
// The volume is the Marschner-Lobb field resampled to N^3 (values in [0, 1]),
// through presets/bonsai.json rescaled to [0, 1].
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <map>
#include <memory>

#include "vri/methods.hpp"
#include "vri/scene.hpp"
#include "tables/table_builder.hpp"
#include "tables/zero_opacity.hpp"
#include "volume/builtin_volumes.hpp"
#include "volume/empty_space.hpp"
#include "volume/macro_cells.hpp"

namespace {

const vri::GridVolume& bench_volume(int n) {
  static std::map<int, std::unique_ptr<vri::GridVolume>> volumes;
  auto& v = volumes[n];
  if (!v) v = std::make_unique<vri::GridVolume>(vri::marschner_lobb({n, n, n}));
  return *v;
}

const vri::TransferFunction& bench_tf() {
  static const vri::TransferFunction tf = [] {
    const auto tf = vri::load_transfer_function(VRI_SOURCE_DIR "/presets/bonsai.json");
    std::vector<vri::ControlPoint> points = tf.points();
    const double lo = tf.s_lo(), hi = tf.s_hi();
    for (auto& p : points) p.s = (p.s - lo) / (hi - lo);
    return vri::TransferFunction(points);
  }();
  return tf;
}

void BM_MacroCells(benchmark::State& state) {
  const vri::GridVolume& volume = bench_volume(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const vri::MacroRanges ranges = vri::compute_macro_ranges(volume);
    benchmark::DoNotOptimize(ranges.lo.data());
  }
}

void BM_Reclassify(benchmark::State& state) {
  const vri::MacroCells cells(bench_volume(static_cast<int>(state.range(0))));
  std::size_t empty = 0;
  for (auto _ : state) {
    const vri::DiscreteTf tf(bench_tf(), 256);
    const vri::EmptySpace space(cells, vri::ZeroOpacity(tf));
    empty = space.empty_count();
    benchmark::DoNotOptimize(empty);
  }
  state.counters["macro_cells"] = static_cast<double>(cells.count());
  state.counters["empty"] = static_cast<double>(empty);
}

void BM_TfEdit(benchmark::State& state) {
  const vri::MacroCells cells(bench_volume(static_cast<int>(state.range(0))));
  const auto builder = vri::make_table_builder("incremental");
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
  for (auto _ : state) {
    const vri::DiscreteTf tf(bench_tf(), 256);
    const vri::PreintegrationTable table = builder->build(tf, 1.0);
    const vri::EmptySpace space(cells, vri::ZeroOpacity(tf));
    benchmark::DoNotOptimize(table.data().data());
    benchmark::DoNotOptimize(space.empty_count());
  }
}

void BM_Preint1Setup(benchmark::State& state) {
  const vri::GridVolume& volume = bench_volume(static_cast<int>(state.range(0)));
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
  vri::MethodSpec spec;
  spec.name = "preint1";
  (void)vri::make_integrator(spec, volume, bench_tf(), {});  // the volume has been rendered once
  for (auto _ : state) {
    const auto integrator = vri::make_integrator(spec, volume, bench_tf(), {});
    benchmark::DoNotOptimize(integrator.get());
  }
}

BENCHMARK(BM_MacroCells)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Reclassify)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TfEdit)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Preint1Setup)->Arg(256)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
