// Pre-integration table build times (docs/PERFORMANCE.md, "Pre-integration tables").
// The transfer function is presets/bonsai.json (tau up to 2 per voxel), slabs of
// one voxel; tables with lengths span 0 .. 2 voxels.
//   BM_Table/<builder>/N/threads         N x N table
//   BM_LengthTable/<builder>/N/M/threads M x N x N table
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include "vri/scene/scene.hpp"
#include "vri/tables/table_builder.hpp"

namespace {

const vri::TransferFunction& bench_tf() {
  static const vri::TransferFunction tf = vri::load_transfer_function(VRI_SOURCE_DIR "/presets/bonsai.json");
  return tf;
}

void BM_Table(benchmark::State& state, const char* builder_name) {
  const vri::DiscreteTf tf(bench_tf(), static_cast<int>(state.range(0)));
  const auto builder = vri::make_table_builder(builder_name);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(1));
  for (auto _ : state) benchmark::DoNotOptimize(builder->build(tf, 1.0).data().data());
}

void BM_LengthTable(benchmark::State& state, const char* builder_name) {
  const vri::DiscreteTf tf(bench_tf(), static_cast<int>(state.range(0)));
  const auto builder = vri::make_table_builder(builder_name);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(2));
  for (auto _ : state)
    benchmark::DoNotOptimize(vri::build_length_table(*builder, tf, static_cast<int>(state.range(1)), 2.0));
}

// Lum et al. 2004, Table 1 sizes; brute stops at 256 (512 would take ~15 s a run).
BENCHMARK_CAPTURE(BM_Table, brute, "brute")
    ->ArgsProduct({{32, 64, 128, 256}, {1}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Table, incremental, "incremental")
    ->ArgsProduct({{32, 64, 128, 256, 512, 1024, 2048}, {1, 2}})
    ->Unit(benchmark::kMillisecond);
// Roettger & Ertl 2002 slice-parallel scheme, 2N steps, fp32 accumulation: O(N^3).
BENCHMARK_CAPTURE(BM_Table, sliced, "sliced")
    ->ArgsProduct({{32, 64, 128, 256}, {1}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Table, engel, "engel")
    ->ArgsProduct({{32, 64, 128, 256, 512, 1024, 2048}, {1}})
    ->Unit(benchmark::kMillisecond);
// Roettger & Ertl 2002 sizes: 64x64x32, 128x128x64, 256x256x128.
BENCHMARK_CAPTURE(BM_LengthTable, incremental, "incremental")
    ->Args({64, 32, 2})
    ->Args({128, 64, 2})
    ->Args({256, 128, 2})
    ->Args({256, 128, 1})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
