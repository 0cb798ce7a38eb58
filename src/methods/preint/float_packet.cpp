#include "methods/march/float_packet.hpp"

#include "core/simd.hpp"
// The AVX2 packets, compiled where simd.hpp allows them (x86-64 with
// VRI_SIMD); float_packet_scalar.cpp is the build without.
#if VRI_HAVE_AVX2_PACKETS
#include "methods/march/packet_lanes.hpp"

namespace vri::detail {

bool packets_available() { return __builtin_cpu_supports("avx2"); }

bool packets_fit(const GridVolume& volume) {
  return packets_available() && volume.size() <= static_cast<std::size_t>(INT_MAX);
}

using namespace lanes8;

// AVX2 without FMA on purpose: GCC fuses a * b + c wherever FMA is enabled
// (even in ISO C++ mode), which would change the bytes against the scalar march.
template <class Lookup, class Value>
__attribute__((target("avx2"))) void march_packet(const GridVolume& volume, const FloatSampler& sampler,
                                                  const Value* values, const Lookup& table, const DiscreteTf& tf,
                                                  const FloatLighting& lighting, const Ray* rays, double h,
                                                  const Leap& leap, Rgba* out) {
  constexpr int steps = Lookup::kSteps;
  Lanes<steps> L{};  // lanes without a ray read cell 0 and entry 0
  const int n = table.size();
  const TableAxis8 axis = axis8(table.axis());
  unsigned active = enter(L, volume, sampler, rays, h, out);
  for (unsigned m = active; m; m &= m - 1) {
    const int l = __builtin_ctz(m);
    // The owned slabs, as march_float takes them: full ones from k to full - 1, and the partial one.
    const long long all = static_cast<long long>(std::floor(L.iv[l].length() / (steps * h)));
    const PieceRange owned = owned_pieces(L.iv[l], steps * h, all + 1);
    L.k[l] = static_cast<int>(owned.begin);
    L.full[l] = static_cast<int>(std::min(owned.end, all));
    L.partial[l] = owned.begin <= all && all < owned.end;
    L.runs[l].start(leap.space, rays[l], L.iv[l].t1);
  }
  const auto finish = [&](int l) {
    const FloatSample front{L.s[0][l], {L.grad[0][0][l], L.grad[0][1][l], L.grad[0][2][l]}, {L.ta[0][l], L.tb[0][l]}};
    if (!L.partial[l])  // the partial slab is another brick's
      out[l] = L.pixel(l);
    else
      out[l] = finish_float<steps>(sampler, values, tf, lighting, rays[l], L.iv[l], L.full[l], h, front, leap,
                                 L.lane(l));
    active &= ~(1u << l);
  };
  // A lane at its stop: the head of march_float's outer loop (leap, next
  // stop) or, past its last full slab, its end. Returns whether it leapt (its
  // new slab is then still to be found). A lane whose empty run reaches the
  // ray's exit ends there: its remaining slabs and its partial slab lie in
  // the run and add exactly nothing (EmptySpace), so it needs no samples.
  const auto head = [&](int l) {
    const long long k = L.k[l], full = L.full[l];
    if (k >= full) {
      finish(l);
      return false;
    }
    const long long j = leap_target(L.runs[l], L.iv[l], h, steps, k, full);
    L.k[l] = static_cast<int>(j);
    if (j == full && j > k && L.runs[l].end() >= L.iv[l].t1) {
      out[l] = L.pixel(l);
      active &= ~(1u << l);
      return false;
    }
    if (j < full)
      L.stop[l] = static_cast<int>(
          leap.space
              ? std::clamp(static_cast<long long>(std::ceil((L.runs[l].end() - L.iv[l].t0) / (steps * h))), j + 1, full)
              : full);
    return j > k;
  };
  // The first heads before the first samples: most rays enter through empty
  // space and leap at once. Then every lane's slab is found (a ray without
  // full slabs uses only its front sample, for its partial slab).
  for (unsigned m = active; m; m &= m - 1)
    if (const int l = __builtin_ctz(m); L.k[l] < L.full[l]) head(l);
  if (!active) return;  // every ray missed the volume or leapt through empty space to its exit
  start_slab(sampler, values, lighting, axis, n, L, active);
  for (unsigned m = active; m; m &= m - 1)
    if (const int l = __builtin_ctz(m); L.k[l] >= L.full[l]) finish(l);
  const __m256i n8 = _mm256_set1_epi32(n);
  while (active) {
    const unsigned before_stop = mask(_mm256_cmpgt_epi32(load(L.stop), load(L.k)));
    unsigned leapt = 0;
    for (unsigned m = active & ~before_stop; m; m &= m - 1)
      if (const int l = __builtin_ctz(m); head(l)) leapt |= 1u << l;
    if (leapt) {
      start_slab(sampler, values, lighting, axis, n, L, leapt);
      for (unsigned m = leapt; m; m &= m - 1)  // leapt to the end: the partial slab from sample `full` Steps
        if (const int l = __builtin_ctz(m); L.k[l] == L.full[l]) finish(l);
    }
    // Early termination (the inner loop's check before each slab).
    const unsigned ended = active & below8(L, leap.termination);
    for (unsigned m = ended; m; m &= m - 1) finish(__builtin_ctz(m));
    if (!active) break;
    // Samples 1 .. Steps of slab k + 1 of every lane and their places on the
    // table axis; past a lane's last full slab its back sample stands in, as
    // in the scalar march.
    const __m256i k = load(L.k), k1 = _mm256_add_epi32(k, _mm256_set1_epi32(1));
    const __m256 beyond = _mm256_castsi256_ps(_mm256_cmpgt_epi32(_mm256_add_epi32(k, _mm256_set1_epi32(2)), load(L.full)));
    const __m256i next_first = _mm256_mullo_epi32(k1, _mm256_set1_epi32(steps));
    const __m256 back_s = load(L.s[steps]), back_w = load(L.w[steps]);
    const __m256i back_i = load(L.i[steps]);
    // (Zeroed first: GCC 12 cannot see that the loop below fills them, -Wmaybe-uninitialized.)
    __m256 next_s[steps + 1]{}, next_w[steps + 1]{}, next_g[steps + 1][3]{}, next_a[steps + 1]{}, next_b[steps + 1]{};
    __m256i next_i[steps + 1]{};
    next_s[0] = back_s, next_w[0] = back_w, next_i[0] = back_i;
    for (int a = 0; a < 3; ++a) next_g[0][a] = load(L.grad[steps][a]);
    next_a[0] = load(L.ta[steps]), next_b[0] = load(L.tb[steps]);
    const __m256 d[3] = {load(L.d[0]), load(L.d[1]), load(L.d[2])};
    for (int j = 1; j <= steps; ++j) {
      Cells8 cells;
      const __m256 s = sample8(sampler, values, L, _mm256_add_epi32(next_first, _mm256_set1_epi32(j)), &cells);
      __m256i i;
      __m256 w;
      place8(axis, s, i, w);
      next_s[j] = _mm256_blendv_ps(s, back_s, beyond);
      next_w[j] = _mm256_blendv_ps(w, back_w, beyond);
      next_i[j] = blend(i, back_i, beyond);
      for (int a = 0; a < 3; ++a) next_g[j][a] = next_g[0][a];  // past the last full slab the back
      next_a[j] = next_a[0], next_b[j] = next_b[0];                 // sample's state stands in too
      if (lighting.shading) {
        const __m256 fresh = _mm256_xor_ps(beyond, _mm256_castsi256_ps(_mm256_set1_epi32(-1)));
        lit_sample(lighting, cells, d, fresh, next_g[j], next_a[j], next_b[j]);
      }
    }
    // Slab k of every lane looked up, lit (slab_colour) and composited front to back.
    __m256 v[4];
    if (!lighting.shading) {
      blend8(table, table.data(), L, v);
    } else if (!lighting.interpolated()) {  // one normal, the mean of the samples' gradients
      blend8(table, table.data(), L, v);
      __m256 mean[3], a, b;
      for (int c = 0; c < 3; ++c) {
        mean[c] = load(L.grad[0][c]);
        for (int j = 1; j <= steps; ++j) mean[c] = _mm256_add_ps(mean[c], load(L.grad[j][c]));
        mean[c] = _mm256_mul_ps(mean[c], _mm256_set1_ps(1.0f / (steps + 1)));
      }
      terms8(*lighting.shading, mean, d, a, b);
      lit_by8(a, b, v);
    } else {
      lit_interpolated8(table, lighting, L, v);
    }
    composite8(L, v);
    // Slab k + 1.
    for (int j = 0; j <= steps; ++j) {
      store(L.s[j], next_s[j]), store(L.w[j], next_w[j]), store(L.i[j], next_i[j]);
      if (lighting.shading) {
        for (int a = 0; a < 3; ++a) store(L.grad[j][a], next_g[j][a]);
        store(L.ta[j], next_a[j]), store(L.tb[j], next_b[j]);
      }
    }
    store(L.entry, spot8<steps>(next_i, n8));
    if constexpr (steps == 2) prefetch_rows8(table, L.entry);
    store(L.k, k1);
  }
}

void march_preint1_packet(const GridVolume& volume, const FloatSampler& sampler, const FloatLookup& table,
                          const DiscreteTf& tf, const FloatLighting& lighting, const Ray* rays, double h,
                          const Leap& leap, Rgba* out) {
  volume.visit(
      [&](auto values) { march_packet(volume, sampler, values.data(), table, tf, lighting, rays, h, leap, out); });
}

void march_preint2_packet(const GridVolume& volume, const FloatSampler& sampler, const SecondOrderFloatLookup& table,
                          const DiscreteTf& tf, const FloatLighting& lighting, const Ray* rays, double h,
                          const Leap& leap, Rgba* out) {
  volume.visit(
      [&](auto values) { march_packet(volume, sampler, values.data(), table, tf, lighting, rays, h, leap, out); });
}

#undef VRI_AVX2

}  // namespace vri::detail
#endif  // VRI_HAVE_AVX2_PACKETS
