// Does a bricked volume layout pay? (issue 8, item 1: "a memory layout that
// suits the caches (bricks if they pay)"; docs/PERFORMANCE.md, "Scaling").
// An experiment beside the renderer, not a part of it: the trilinear
// sampling of the float paths (FloatSampler's cell and fractions, uint8
// corners converted to float) on an N^3 uint8 volume in three layouts,
//   0 linear    x fastest, as GridVolume stores it;
//   1 bricks    8^3-sample bricks, bricks and the samples in them x fastest
//               (the same memory; each corner addressed on its own);
//   2 aprons    8^3 cells a brick stored with a one-sample apron (9^3
//               samples, 1.42x the memory), so a cell's 8 corners are always
//               in one brick at fixed offsets;
// along the rays of a 512x512 perspective view of the whole volume from a
// diagonal (30 degrees), step 1 voxel, the rays of each tile
// row of 16 pixels marched 8 at a time in lockstep as the packets do, the
// tiles in row order, one thread. Reports ns per sample.
//   BM_Layout/<N>/<layout>
// Run: ./build/bench/bench_brick_layout --benchmark_repetitions=3
//      --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "vri/camera.hpp"
#include "vri/geometry.hpp"

namespace {

constexpr int kBrick = 8;

struct Layouts {
  int n;
  std::vector<std::uint8_t> linear, bricks, aprons;
  int bricks_per_axis;
};

// A smooth field with some detail (the values do not matter, the addresses do).
std::uint8_t value(int n, int i, int j, int k) {
  const double x = double(i) / n, y = double(j) / n, z = double(k) / n;
  return static_cast<std::uint8_t>(127.5 + 127.5 * std::sin(9 * x) * std::cos(7 * y) * std::sin(5 * z + 3 * x));
}

const Layouts& layouts(int n) {
  static std::map<int, std::unique_ptr<Layouts>> cache;
  auto& l = cache[n];
  if (l) return *l;
  l = std::make_unique<Layouts>();
  l->n = n;
  const int b = (n - 1 + kBrick - 1) / kBrick;  // bricks of cells a side
  l->bricks_per_axis = b;
  const std::size_t nn = std::size_t(n) * n * n;
  l->linear.resize(nn);
  l->bricks.assign(std::size_t(b + 1) * (b + 1) * (b + 1) * kBrick * kBrick * kBrick, 0);
  l->aprons.assign(std::size_t(b) * b * b * 9 * 9 * 9, 0);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::uint8_t v = value(n, i, j, k);
        l->linear[i + std::size_t(n) * (j + std::size_t(n) * k)] = v;
        const std::size_t brick = (std::size_t(k / kBrick) * (b + 1) + j / kBrick) * (b + 1) + i / kBrick;
        l->bricks[brick * 512 + ((k % kBrick) * kBrick + j % kBrick) * kBrick + i % kBrick] = v;
        // Every apron brick holding this sample (up to 8: the sample sits on faces shared by bricks).
        for (int bk = std::max(0, (k - 1) / kBrick); bk <= std::min(b - 1, k / kBrick); ++bk)
          for (int bj = std::max(0, (j - 1) / kBrick); bj <= std::min(b - 1, j / kBrick); ++bj)
            for (int bi = std::max(0, (i - 1) / kBrick); bi <= std::min(b - 1, i / kBrick); ++bi) {
              const int li = i - bi * kBrick, lj = j - bj * kBrick, lk = k - bk * kBrick;
              if (li > kBrick || lj > kBrick || lk > kBrick) continue;
              const std::size_t a = (std::size_t(bk) * b + bj) * b + bi;
              l->aprons[a * 729 + (lk * 9 + lj) * 9 + li] = v;
            }
      }
  return *l;
}

float lerp(float a, float b, float f) { return a + f * (b - a); }

float trilinear(const std::array<float, 8>& c, const float* f) {
  return lerp(lerp(lerp(c[0], c[1], f[0]), lerp(c[2], c[3], f[0]), f[1]),
              lerp(lerp(c[4], c[5], f[0]), lerp(c[6], c[7], f[0]), f[1]), f[2]);
}

// The sample at grid position (x, y, z) in the given layout.
template <int Layout>
float sample(const Layouts& l, double x, double y, double z) {
  const int n = l.n, top = n - 1;
  int c[3];
  float f[3];
  const double u[3] = {x, y, z};
  for (int a = 0; a < 3; ++a) {
    const double v = std::clamp(u[a], 0.0, double(top));
    c[a] = std::min(static_cast<int>(v), n - 2);
    f[a] = static_cast<float>(v - c[a]);
  }
  std::array<float, 8> v;
  if constexpr (Layout == 0) {
    const std::size_t sy = n, sz = std::size_t(n) * n;
    const std::uint8_t* p = l.linear.data() + c[0] + sy * c[1] + sz * c[2];
    v = {float(p[0]), float(p[1]), float(p[sy]), float(p[sy + 1]),
         float(p[sz]), float(p[sz + 1]), float(p[sz + sy]), float(p[sz + sy + 1])};
  } else if constexpr (Layout == 1) {
    const int b = l.bricks_per_axis + 1;
    for (int corner = 0; corner < 8; ++corner) {
      const int i = c[0] + (corner & 1), j = c[1] + ((corner >> 1) & 1), k = c[2] + (corner >> 2);
      const std::size_t brick = (std::size_t(k >> 3) * b + (j >> 3)) * b + (i >> 3);
      v[corner] = float(l.bricks[brick * 512 + (((k & 7) << 3 | (j & 7)) << 3 | (i & 7))]);
    }
  } else {
    const int b = l.bricks_per_axis;
    const int bi = c[0] >> 3, bj = c[1] >> 3, bk = c[2] >> 3;
    const std::uint8_t* p = l.aprons.data() + ((std::size_t(bk) * b + bj) * b + bi) * 729 +
                            ((c[2] & 7) * 9 + (c[1] & 7)) * 9 + (c[0] & 7);
    v = {float(p[0]), float(p[1]), float(p[9]), float(p[10]), float(p[81]), float(p[82]), float(p[90]), float(p[91])};
  }
  return trilinear(v, f);
}

template <int Layout>
void BM_Layout(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Layouts& l = layouts(n);
  const double c = (n - 1) / 2.0;
  vri::CameraSpec spec;
  spec.target = {c, c, c};
  spec.eye = {c + 1.3 * n, c + 1.0 * n, c + 1.9 * n};
  const vri::Camera camera(spec);
  constexpr int kTile = 16, kLanes = 8;
  long long samples = 0;
  float sink = 0;
  for (auto _ : state) {
    samples = 0;
    for (int ty = 0; ty < spec.height; ty += kTile)
      for (int tx = 0; tx < spec.width; tx += kTile)
        for (int y = ty; y < ty + kTile; ++y)
          for (int x0 = tx; x0 < tx + kTile; x0 += kLanes) {
            // 8 rays in lockstep: sample k of every ray, then k + 1.
            vri::Vec3 u[kLanes], d[kLanes];
            long long count[kLanes], longest = 0;
            for (int lane = 0; lane < kLanes; ++lane) {
              const vri::Ray ray = camera.ray(x0 + lane, y);
              const auto iv = vri::clip_to_box(ray, {0, 0, 0}, {double(n - 1), double(n - 1), double(n - 1)});
              count[lane] = iv ? static_cast<long long>(iv->length()) : 0;
              u[lane] = iv ? ray.at(iv->t0) : vri::Vec3{0, 0, 0};
              d[lane] = ray.dir;
              longest = std::max(longest, count[lane]);
            }
            for (long long k = 0; k < longest; ++k)
              for (int lane = 0; lane < kLanes; ++lane)
                if (k < count[lane]) {
                  const vri::Vec3 p = u[lane] + double(k) * d[lane];
                  sink += sample<Layout>(l, p.x, p.y, p.z);
                  ++samples;
                }
          }
    benchmark::DoNotOptimize(sink);
  }
  state.counters["ns_per_sample"] =
      benchmark::Counter(double(samples) * state.iterations(), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["samples"] = double(samples);
}

BENCHMARK_TEMPLATE(BM_Layout, 0)->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Layout, 1)->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Layout, 2)->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
