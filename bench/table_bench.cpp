// Pre-integration table build times (docs/PERFORMANCE.md, "Pre-integration tables").
// The transfer function is presets/bonsai.json (tau up to 2 per voxel), slabs of
// one voxel; tables with lengths span 0 .. 2 voxels.
//   BM_Table/<builder>/N/threads         N x N table
//   BM_LengthTable/<builder>/N/M/threads M x N x N table
//   BM_ExactSlab/<way>/bins      one exact slab across `bins` table bins
//                                (presets/engine.json, 256 bins, half a voxel):
//                                exact_index_slab ("runs": a straight run of
//                                bins one piece, four weights at a time)
//                                against every bin a piece, one by one, with
//                                linear_piece ("bins_one_by_one")
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include "vri/scene.hpp"
#include "tables/slab_integral.hpp"
#include "tables/table_builder.hpp"

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

// The partial last slab of a ray that leaves the engine through its data
// (float_march.hpp, last_slabs): scalars 14 bins apart on average there.
void BM_ExactSlab(benchmark::State& state, bool runs) {
  static const vri::DiscreteTf tf(vri::load_transfer_function(VRI_SOURCE_DIR "/presets/engine.json"), 256);
  const double bins = static_cast<double>(state.range(0));
  const auto piece = [](const vri::TfSample& p, const vri::TfSample& q, double d) {
    return vri::linear_piece(p, q, d).forward;
  };
  double u = 0;
  for (auto _ : state) {
    // Backs in 120 .. 180 (where the engine is opaque), fronts `bins` higher.
    u = u < 60 ? u + 0.37 : 0;
    const double u_f = 120 + u + bins, u_b = 120 + u;
    benchmark::DoNotOptimize(runs ? vri::exact_index_slab(tf, u_f, u_b, 0.5)
                                  : vri::integrate_slab(tf, u_f, u_b, 0.5, piece, vri::SlabPieces::Bins));
  }
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

BENCHMARK_CAPTURE(BM_ExactSlab, runs, true)->Arg(1)->Arg(4)->Arg(14)->Arg(64);
BENCHMARK_CAPTURE(BM_ExactSlab, bins_one_by_one, false)->Arg(1)->Arg(4)->Arg(14)->Arg(64);

}  // namespace

BENCHMARK_MAIN();
