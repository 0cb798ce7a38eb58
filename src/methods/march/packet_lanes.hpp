#pragma once
// The 8-lane primitives of the AVX2 packet marches (float_packet.cpp for
// preint1 and preint2, float_packet_riemann.cpp for riemann): the lanes'
// ray state, sampling, table lookups, exp and log, shading - each the
// scalar float path's operations in the same order, so a packet's pixels
// are the scalar march's bytes. Included only where simd.hpp allows AVX2
// packets (VRI_HAVE_AVX2_PACKETS).
#include <immintrin.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "methods/preint/float_march.hpp"
#include "float_packet.hpp"
#include "methods/riemann/float_riemann.hpp"

namespace vri::detail::lanes8 {

// What the lanes composited so far, in double: FrontToBack (ray_steps.hpp)
// a lane each.
struct Composited8 {
  alignas(32) double r[kPacket], g[kPacket], b[kPacket], T[kPacket];
  Rgba pixel(int l) const { return {r[l], g[l], b[l], 1 - T[l]}; }
  FrontToBack lane(int l) const {
    FrontToBack acc;
    acc.T = T[l], acc.C[0] = r[l], acc.C[1] = g[l], acc.C[2] = b[l];
    return acc;
  }
};

// What every march keeps per ray, a lane each: its sample positions u0 + k du
// in grid units, its clipped interval and what it composited so far.
struct RayLanes : Composited8 {
  alignas(32) double ux[kPacket], uy[kPacket], uz[kPacket];  // u0
  alignas(32) double dx[kPacket], dy[kPacket], dz[kPacket];  // du
  alignas(32) float d[3][kPacket];  // the direction, for lighting
  Interval iv[kPacket];
  MacroRuns runs[kPacket];  // the leaps over empty macro cells
};

// Clips the rays to the volume and starts the lanes that hit it (steps of h
// from the entry, T = 1); a ray that misses gets a transparent pixel. Returns
// the mask of the lanes started.
inline unsigned enter(RayLanes& L, const GridVolume& volume, const FloatSampler& sampler, const Ray* rays, double h,
               Rgba* out) {
  unsigned active = 0;
  for (int l = 0; l < kPacket; ++l) {
    const auto iv = volume.clip(rays[l]);  // a brick's: the whole ray's interval and its owned window
    if (!iv) {
      out[l] = {0, 0, 0, 0};
      continue;
    }
    L.iv[l] = *iv;
    const Vec3 u0 = sampler.grid(rays[l].at(iv->t0)), du = sampler.grid_step(rays[l].dir * h);
    L.ux[l] = u0.x, L.uy[l] = u0.y, L.uz[l] = u0.z, L.dx[l] = du.x, L.dy[l] = du.y, L.dz[l] = du.z;
    L.T[l] = 1;
    L.d[0][l] = static_cast<float>(rays[l].dir.x), L.d[1][l] = static_cast<float>(rays[l].dir.y);
    L.d[2][l] = static_cast<float>(rays[l].dir.z);
    active |= 1u << l;
  }
  return active;
}

// Each ray's state, a lane each: what march_float keeps in locals, for slabs
// of Steps steps (1: preint1, 2: preint2).
template <int Steps>
struct Lanes : RayLanes {
  alignas(32) int k[kPacket], stop[kPacket], full[kPacket];
  bool partial[kPacket];  // the lane owns the partial last slab (march_float)
  // The slab's samples, front to back: scalar, entry and weight on the table axis.
  alignas(32) float s[Steps + 1][kPacket];
  alignas(32) int i[Steps + 1][kPacket];
  alignas(32) float w[Steps + 1][kPacket];
  alignas(32) float grad[Steps + 1][3][kPacket];  // `sampled`: the samples' gradients
  alignas(32) float ta[Steps + 1][kPacket], tb[Steps + 1][kPacket];  // `interpolated`: their shading terms
  alignas(32) int entry[kPacket];  // the slab's spot (find): its first entry's offset
};

#define VRI_AVX2 __attribute__((target("avx2"), always_inline)) inline

// Lanes 4 half .. 4 half + 3 of 8 floats as doubles.
VRI_AVX2 __m256d half_pd(__m256 x, int half) {
  return _mm256_cvtps_pd(half ? _mm256_extractf128_ps(x, 1) : _mm256_castps256_ps128(x));
}

// FrontToBack::add of each lane's slab v (premultiplied r, g, b and alpha, in
// float).
VRI_AVX2 void composite8(Composited8& L, const __m256 (&v)[4]) {
  for (int half = 0; half < 2; ++half) {
    const int o = 4 * half;
    const __m256d T = _mm256_load_pd(L.T + o);
    double* C[3] = {L.r + o, L.g + o, L.b + o};
    for (int c = 0; c < 3; ++c)
      _mm256_store_pd(C[c], _mm256_add_pd(_mm256_load_pd(C[c]), _mm256_mul_pd(T, half_pd(v[c], half))));
    _mm256_store_pd(L.T + o, _mm256_mul_pd(T, _mm256_sub_pd(_mm256_set1_pd(1), half_pd(v[3], half))));
  }
}

// FrontToBack::add_step of each lane's Riemann step: colour c over a step of
// transparency e (floats).
VRI_AVX2 void riemann_composite8(Composited8& L, const __m256 (&c)[4], __m256 e) {
  for (int half = 0; half < 2; ++half) {
    const int o = 4 * half;
    const __m256d T = _mm256_load_pd(L.T + o), ed = half_pd(e, half);
    const __m256d w = _mm256_mul_pd(T, _mm256_sub_pd(_mm256_set1_pd(1), ed));
    double* C[3] = {L.r + o, L.g + o, L.b + o};
    for (int k = 0; k < 3; ++k)
      _mm256_store_pd(C[k], _mm256_add_pd(_mm256_load_pd(C[k]), _mm256_mul_pd(w, half_pd(c[k], half))));
    _mm256_store_pd(L.T + o, _mm256_mul_pd(T, ed));
  }
}

// The lanes whose transmittance is below `termination` (none when it is 0:
// T >= 0, and the compares are skipped).
VRI_AVX2 unsigned below8(const Composited8& L, double termination) {
  if (!(termination > 0)) return 0;
  const __m256d t = _mm256_set1_pd(termination);
  return static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(_mm256_load_pd(L.T), t, _CMP_LT_OQ))) |
         static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(_mm256_load_pd(L.T + 4), t, _CMP_LT_OQ))) << 4;
}

// One axis of FloatSampler::at for the 8 lanes' samples k: the cell
// min(trunc(clamp(u0 + k du, 0, top)), last) and the float fraction in it,
// with the same double operations as the scalar code.
VRI_AVX2 void cell_axis(const double* u0, const double* du, __m256i k, double top, int last, __m256i& cell,
                        __m256& fraction) {
  const __m256d zero = _mm256_setzero_pd(), hi = _mm256_set1_pd(top);
  __m128i c[2];
  __m128 f[2];
  for (int half = 0; half < 2; ++half) {
    const __m256d kd = _mm256_cvtepi32_pd(half ? _mm256_extracti128_si256(k, 1) : _mm256_castsi256_si128(k));
    __m256d x = _mm256_add_pd(_mm256_load_pd(u0 + 4 * half), _mm256_mul_pd(kd, _mm256_load_pd(du + 4 * half)));
    x = _mm256_min_pd(hi, _mm256_max_pd(zero, x));  // std::clamp: x < 0 ? 0 : top < x ? top : x
    c[half] = _mm_min_epi32(_mm256_cvttpd_epi32(x), _mm_set1_epi32(last));
    f[half] = _mm256_cvtpd_ps(_mm256_sub_pd(x, _mm256_cvtepi32_pd(c[half])));
  }
  cell = _mm256_set_m128i(c[1], c[0]);
  fraction = _mm256_set_m128(f[1], f[0]);
}

VRI_AVX2 __m256 lerp(__m256 a, __m256 b, __m256 f) { return _mm256_add_ps(a, _mm256_mul_ps(f, _mm256_sub_ps(b, a))); }

VRI_AVX2 __m256 load(const float* p) { return _mm256_load_ps(p); }
VRI_AVX2 __m256i load(const int* p) { return _mm256_load_si256(reinterpret_cast<const __m256i*>(p)); }
VRI_AVX2 void store(float* p, __m256 v) { _mm256_store_ps(p, v); }
VRI_AVX2 void store(int* p, __m256i v) { _mm256_store_si256(reinterpret_cast<__m256i*>(p), v); }
VRI_AVX2 unsigned mask(__m256i m) { return static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(m))); }

// Four registers of two 4-float entries each (lanes l and l + 4 in
// register l) as 4 vectors (r, g, b, alpha) of 8 lanes: transposed 4 by 4
// in each half.
VRI_AVX2 void transpose8(const __m256 (&q)[4], __m256 channel[4]) {
  const __m256 t0 = _mm256_unpacklo_ps(q[0], q[1]), t1 = _mm256_unpackhi_ps(q[0], q[1]);
  const __m256 t2 = _mm256_unpacklo_ps(q[2], q[3]), t3 = _mm256_unpackhi_ps(q[2], q[3]);
  channel[0] = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
  channel[1] = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
  channel[2] = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
  channel[3] = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2));
}

// The 4-float table entries data + entry[l] + add of the 8 lanes, as 4
// vectors (r, g, b, alpha) of 8 lanes.
VRI_AVX2 void corner(const float* data, const int* entry, int add, __m256 channel[4]) {
  __m256 q[4];
  for (int l = 0; l < 4; ++l) q[l] = _mm256_loadu2_m128(data + entry[l + 4] + add, data + entry[l] + add);
  transpose8(q, channel);
}

// Lanes 0 1 4 5 2 3 6 7 (what shuffle_ps leaves) back in order.
VRI_AVX2 __m256 order(__m256 v) {
  return _mm256_castpd_ps(_mm256_permute4x64_pd(_mm256_castps_pd(v), _MM_SHUFFLE(3, 1, 2, 0)));
}

// Two lanes' pairs (base[i], base[i + 1]) as one 128-bit register. The pairs
// are only 4-byte aligned: read through memcpy (the same movsd/movhpd, without
// the misaligned double access UBSan rightly reports).
VRI_AVX2 __m128d pairs(const float* base, int i, int j) {
  double lo, hi;
  std::memcpy(&lo, base + i, sizeof lo);
  std::memcpy(&hi, base + j, sizeof hi);
  return _mm_set_pd(hi, lo);
}

// The 8 lanes' neighbouring samples base[index[l]] and base[index[l] + 1],
// in float (exactly, as the scalar path converts them), as vectors lo and hi:
// each pair of floats read as one 8-byte element, then split.
VRI_AVX2 void pair8(const float* base, const int* index, __m256& lo, __m256& hi) {
  const __m256 a = _mm256_castpd_ps(_mm256_set_m128d(pairs(base, index[2], index[3]), pairs(base, index[0], index[1])));
  const __m256 b = _mm256_castpd_ps(_mm256_set_m128d(pairs(base, index[6], index[7]), pairs(base, index[4], index[5])));
  lo = order(_mm256_shuffle_ps(a, b, _MM_SHUFFLE(2, 0, 2, 0)));
  hi = order(_mm256_shuffle_ps(a, b, _MM_SHUFFLE(3, 1, 3, 1)));
}

// The corner pairs (v[i], v[i + 1]) along x of the 8 lanes' cells at (y, z)
// = (0, 0), (1, 0), (0, 1), (1, 1): i = index + {0, sy, sz, sz + sy}, in
// float (exactly). Floats are read as 8-byte pairs (pair8). 1- and 2-byte
// samples are gathered 32 bits a lane: a 2-byte pair is the 32 bits read,
// a 1-byte pair the low half of the 4 bytes at i, except at (1, 1), where
// the 4 bytes end at i + 1 (read from i - 2: the high half), so that no read
// passes the last sample (a cell's first corner lies below the grid's last
// point on every axis, so i + 1 <= the last index only there). The gathers
// take the place of 8 scalar loads and inserts a pair (1.01x the frame on
// the turned engine, one thread).
template <class T>
VRI_AVX2 void corner_pairs8(const T* v, __m256i index, std::size_t sy, std::size_t sz, __m256 lo[4], __m256 hi[4]) {
  const std::size_t row[4] = {0, sy, sz, sz + sy};
  if constexpr (std::is_same_v<T, float>) {
    alignas(32) int at[kPacket];
    _mm256_store_si256(reinterpret_cast<__m256i*>(at), index);
    for (int r = 0; r < 4; ++r) pair8(v + row[r], at, lo[r], hi[r]);
  } else {
    for (int r = 0; r < 4; ++r) {
      if constexpr (sizeof(T) == 1) {
        const int back = r == 3 ? 2 : 0;
        const __m256i p = _mm256_i32gather_epi32(reinterpret_cast<const int*>(v + row[r] - back), index, 1);
        const __m256i q = _mm256_srli_epi32(p, 8 * back);
        lo[r] = _mm256_cvtepi32_ps(_mm256_and_si256(q, _mm256_set1_epi32(0xff)));
        hi[r] = _mm256_cvtepi32_ps(_mm256_and_si256(_mm256_srli_epi32(q, 8), _mm256_set1_epi32(0xff)));
      } else {
        const __m256i p = _mm256_i32gather_epi32(reinterpret_cast<const int*>(v + row[r]), index, 2);
        if constexpr (std::is_signed_v<T>) {  // sign-extended by the arithmetic shifts
          lo[r] = _mm256_cvtepi32_ps(_mm256_srai_epi32(_mm256_slli_epi32(p, 16), 16));
          hi[r] = _mm256_cvtepi32_ps(_mm256_srai_epi32(p, 16));
        } else {
          lo[r] = _mm256_cvtepi32_ps(_mm256_and_si256(p, _mm256_set1_epi32(0xffff)));
          hi[r] = _mm256_cvtepi32_ps(_mm256_srli_epi32(p, 16));
        }
      }
    }
  }
}

// FloatSampler::cell of the 8 lanes' samples k: each lane's first corner
// and the fractions.
struct Cells8 {
  __m256i index;
  __m256 fx, fy, fz;
};
template <class Lanes>
VRI_AVX2 Cells8 cells8(const FloatSampler& sampler, const Lanes& L, __m256i k) {
  __m256i cx, cy, cz;
  Cells8 c;
  cell_axis(L.ux, L.dx, k, sampler.top(0), sampler.last_cell(0), cx, c.fx);
  cell_axis(L.uy, L.dy, k, sampler.top(1), sampler.last_cell(1), cy, c.fy);
  cell_axis(L.uz, L.dz, k, sampler.top(2), sampler.last_cell(2), cz, c.fz);
  const int sy = static_cast<int>(sampler.stride_y()), sz = static_cast<int>(sampler.stride_z());
  c.index = _mm256_add_epi32(cx, _mm256_add_epi32(_mm256_mullo_epi32(cy, _mm256_set1_epi32(sy)),
                                                  _mm256_mullo_epi32(cz, _mm256_set1_epi32(sz))));
  return c;
}

// FloatSampler::at of the 8 lanes' samples k.
template <class Lanes, class T>
VRI_AVX2 __m256 sample8(const FloatSampler& sampler, const T* v, const Lanes& L, __m256i k, Cells8* cells = nullptr) {
  const Cells8 c = cells8(sampler, L, k);
  if (cells) *cells = c;
  const std::size_t sy = sampler.stride_y(), sz = sampler.stride_z();
  __m256 lo[4], hi[4];
  corner_pairs8(v, c.index, sy, sz, lo, hi);
  const __m256 c00 = lerp(lo[0], hi[0], c.fx), c10 = lerp(lo[1], hi[1], c.fx);
  const __m256 c01 = lerp(lo[2], hi[2], c.fx), c11 = lerp(lo[3], hi[3], c.fx);
  return lerp(lerp(c00, c10, c.fy), lerp(c01, c11, c.fy), c.fz);
}

// FloatAxis::place of 8 scalars: entry i and weight w on the table axis.
struct TableAxis8 {
  __m256 lo, scale, top;
  __m256i last;
};
VRI_AVX2 TableAxis8 axis8(const FloatAxis& a) {
  return {_mm256_set1_ps(a.lo()), _mm256_set1_ps(a.scale()), _mm256_set1_ps(a.top()), _mm256_set1_epi32(a.size() - 2)};
}
VRI_AVX2 void place8(const TableAxis8& axis, __m256 s, __m256i& i, __m256& w) {
  const __m256 u = _mm256_min_ps(axis.top, _mm256_max_ps(_mm256_setzero_ps(),
                                                         _mm256_mul_ps(_mm256_sub_ps(s, axis.lo), axis.scale)));
  i = _mm256_min_epi32(_mm256_cvttps_epi32(u), axis.last);
  w = _mm256_sub_ps(u, _mm256_cvtepi32_ps(i));
}

// All ones in the lanes whose bit is set.
VRI_AVX2 __m256 lane_mask(unsigned bits) {
  const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
  return _mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(static_cast<int>(bits)), bit), bit));
}
VRI_AVX2 __m256i blend(__m256i a, __m256i b, __m256 m) {
  return _mm256_castps_si256(_mm256_blendv_ps(_mm256_castsi256_ps(a), _mm256_castsi256_ps(b), m));
}

// The slab's spot from its samples' entries on the table axis (find): the
// offset of entry (i_0, ..., i_Steps) in floats.
template <int Steps>
VRI_AVX2 __m256i spot8(const __m256i (&i)[Steps + 1], __m256i n) {
  __m256i e = i[0];
  for (int j = 1; j <= Steps; ++j) e = _mm256_add_epi32(_mm256_mullo_epi32(e, n), i[j]);
  return _mm256_slli_epi32(e, 2);
}

// The rows a second-order slab lookup of the 8 lanes will read (blend8
// below), asked for as soon as the spots are known, a slab ahead, so that
// the loads overlap the next slab's sampling: the table (256^3 x 4 floats,
// 256 MiB, by default) lives in memory. (preint1's, 1 MiB, gained
// nothing: engine's turned view took 1.035x as long, median of 9.)
VRI_AVX2 void prefetch_rows8(const SecondOrderFloatLookup& table, const int* entry) {
  for (int l = 0; l < kPacket; ++l) table.prefetch(entry[l]);
}

// The slab lookups of the 8 lanes in the table `data` of the lookup's layout
// (FloatLookup::blend, SecondOrderFloatLookup::blend with lanes as vectors,
// the same operations in the same order).
VRI_AVX2 void blend8(const FloatLookup& table, const float* data, const Lanes<1>& L, __m256 v[4]) {
  const int row = 4 * table.size();
  __m256 e00[4], e01[4], e10[4], e11[4];
  corner(data, L.entry, 0, e00);
  corner(data, L.entry, 4, e01);
  corner(data, L.entry, row, e10);
  corner(data, L.entry, row + 4, e11);
  const __m256 wf = load(L.w[0]), wb = load(L.w[1]);
  for (int c = 0; c < 4; ++c) v[c] = lerp(lerp(e00[c], e01[c], wb), lerp(e10[c], e11[c], wb), wf);
}
// SecondOrderFloatLookup::blend of the 8 lanes at their entries in the
// table `data` of the lookup's layout.
VRI_AVX2 void blend8(const SecondOrderFloatLookup& table, const float* data, const Lanes<2>& L, __m256 v[4]) {
  const int row = static_cast<int>(table.row()), plane = static_cast<int>(table.plane());
  const __m256 wf = load(L.w[0]), wm = load(L.w[1]), wb = load(L.w[2]);
  __m256 c[2][2][4];  // along s_b at (f, m), f and m each 0 or 1
  for (int f = 0; f < 2; ++f)
    for (int m = 0; m < 2; ++m) {
      __m256 lo[4], hi[4];
      corner(data, L.entry, f * plane + m * row, lo);
      corner(data, L.entry, f * plane + m * row + 4, hi);
      for (int ch = 0; ch < 4; ++ch) c[f][m][ch] = lerp(lo[ch], hi[ch], wb);
    }
  for (int ch = 0; ch < 4; ++ch) v[ch] = lerp(lerp(c[0][0][ch], c[0][1][ch], wm), lerp(c[1][0][ch], c[1][1][ch], wm), wf);
}

// exp_neg (float_math.hpp) on 8 lanes, the same operations in the same order.
VRI_AVX2 __m256 exp_neg8(__m256 x) {
  using namespace exp_poly;
  const __m256 y = _mm256_max_ps(_mm256_xor_ps(x, _mm256_set1_ps(-0.0f)), _mm256_set1_ps(kMin));
  const __m256 n = _mm256_floor_ps(_mm256_add_ps(_mm256_mul_ps(y, _mm256_set1_ps(kLog2e)), _mm256_set1_ps(0.5f)));
  const __m256 r = _mm256_sub_ps(_mm256_sub_ps(y, _mm256_mul_ps(n, _mm256_set1_ps(kLn2Hi))),
                                 _mm256_mul_ps(n, _mm256_set1_ps(kLn2Lo)));
  __m256 p = _mm256_set1_ps(kP[0]);
  for (int i = 1; i < 6; ++i) p = _mm256_add_ps(_mm256_mul_ps(p, r), _mm256_set1_ps(kP[i]));
  const __m256 e = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(p, _mm256_mul_ps(r, r)), r), _mm256_set1_ps(1.0f));
  const __m256i bits = _mm256_slli_epi32(_mm256_add_epi32(_mm256_cvttps_epi32(n), _mm256_set1_epi32(127)), 23);
  return _mm256_mul_ps(e, _mm256_castsi256_ps(bits));
}

// log_pos (float_math.hpp) on 8 lanes, the same operations in the same order
// (max with the bound first, as std::max(x, bound) keeps x when it is NaN).
VRI_AVX2 __m256 log8(__m256 x) {
  using namespace log_poly;
  const __m256i bits = _mm256_castps_si256(_mm256_max_ps(_mm256_set1_ps(kMin), x));
  __m256 e = _mm256_cvtepi32_ps(_mm256_sub_epi32(_mm256_srli_epi32(bits, 23), _mm256_set1_epi32(126)));
  __m256 m = _mm256_castsi256_ps(_mm256_or_si256(_mm256_and_si256(bits, _mm256_set1_epi32(static_cast<int>(0x807fffffu))),
                                                 _mm256_set1_epi32(0x3f000000)));
  const __m256 one = _mm256_set1_ps(1.0f), low = _mm256_cmp_ps(m, _mm256_set1_ps(kSqrtHalf), _CMP_LT_OQ);
  e = _mm256_blendv_ps(e, _mm256_sub_ps(e, one), low);
  m = _mm256_blendv_ps(_mm256_sub_ps(m, one), _mm256_sub_ps(_mm256_add_ps(m, m), one), low);
  const __m256 z = _mm256_mul_ps(m, m);
  __m256 y = _mm256_set1_ps(kQ[0]);
  for (int i = 1; i < 9; ++i) y = _mm256_add_ps(_mm256_mul_ps(y, m), _mm256_set1_ps(kQ[i]));
  y = _mm256_mul_ps(_mm256_mul_ps(y, m), z);
  y = _mm256_add_ps(y, _mm256_mul_ps(e, _mm256_set1_ps(exp_poly::kLn2Lo)));
  y = _mm256_sub_ps(y, _mm256_mul_ps(_mm256_set1_ps(0.5f), z));
  return _mm256_add_ps(_mm256_add_ps(m, y), _mm256_mul_ps(e, _mm256_set1_ps(exp_poly::kLn2Hi)));
}

// FloatShading::gradient of the 8 lanes' cells: component a gathered at the
// 8 corners of each lane's cell (3 floats a grid point), interpolated as
// FloatSampler::interpolate does.
VRI_AVX2 void gradient8(const FloatShading& shading, const Cells8& c, __m256 g[3]) {
  const __m256i first = _mm256_mullo_epi32(c.index, _mm256_set1_epi32(3));
  const int sy = static_cast<int>(shading.stride_y()), sz = static_cast<int>(shading.stride_z());
  const int offset[8] = {0, 3, sy, sy + 3, sz, sz + 3, sz + sy, sz + sy + 3};
  for (int a = 0; a < 3; ++a) {
    __m256 v[8];
    for (int corner = 0; corner < 8; ++corner)
      v[corner] = _mm256_i32gather_ps(shading.data() + a + offset[corner], first, 4);
    g[a] = lerp(lerp(lerp(v[0], v[1], c.fx), lerp(v[2], v[3], c.fx), c.fy),
                lerp(lerp(v[4], v[5], c.fx), lerp(v[6], v[7], c.fx), c.fy), c.fz);
  }
}

// FloatShading::terms of 8 gradients and directions: (a, b) per lane.
VRI_AVX2 void terms8(const FloatShading& shading, const __m256 g[3], const __m256 d[3], __m256& a, __m256& b) {
  const __m256 len = _mm256_sqrt_ps(
      _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(g[0], g[0]), _mm256_mul_ps(g[1], g[1])), _mm256_mul_ps(g[2], g[2])));
  const __m256 normal = _mm256_and_ps(_mm256_cmp_ps(len, _mm256_set1_ps(shading.flat()), _CMP_GE_OQ),
                                      _mm256_cmp_ps(len, _mm256_setzero_ps(), _CMP_NEQ_OQ));
  const __m256 dot = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(g[0], d[0]), _mm256_mul_ps(g[1], d[1])),
                                   _mm256_mul_ps(g[2], d[2]));
  const __m256 sign = _mm256_set1_ps(-0.0f);
  const __m256 x = _mm256_div_ps(_mm256_andnot_ps(sign, dot), len);
  const __m256 power = exp_neg8(_mm256_xor_ps(_mm256_mul_ps(_mm256_set1_ps(shading.shininess()), log8(x)), sign));
  const __m256 flat_a = _mm256_set1_ps(shading.ka() + shading.kd());
  a = _mm256_blendv_ps(flat_a, _mm256_add_ps(_mm256_set1_ps(shading.ka()), _mm256_mul_ps(_mm256_set1_ps(shading.kd()), x)),
                       normal);
  b = _mm256_and_ps(_mm256_mul_ps(_mm256_set1_ps(shading.ks()), power), normal);
}

// `interpolated` lighting of the 8 lanes' slabs: lit_weighted (first order)
// and lit_lagrange (second order) of float_march.hpp with lanes as vectors,
// the same operations in the same order.
VRI_AVX2 void lit_interpolated8(const FloatLookup& table, const FloatLighting& lighting, const Lanes<1>& L,
                                __m256 v[4]) {
  __m256 front[4], back[4];
  blend8(table, lighting.weighted[0], L, front);
  blend8(table, lighting.weighted[1], L, back);
  const __m256 fa = load(L.ta[0]), fb = load(L.tb[0]), ba = load(L.ta[1]), bb = load(L.tb[1]);
  const __m256 specular =
      _mm256_add_ps(_mm256_mul_ps(fb, _mm256_sub_ps(front[3], back[3])), _mm256_mul_ps(bb, back[3]));
  for (int c = 0; c < 3; ++c)
    v[c] = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(fa, front[c]), _mm256_mul_ps(ba, back[c])), specular);
  v[3] = front[3];
}
// lit_lagrange of 8 lanes: the full, middle and back tables' entries and the
// three samples' shading terms (a[j], b[j]).
VRI_AVX2 void lagrange8(const __m256 full[4], const __m256 middle[4], const __m256 back[4], const __m256 a[3],
                        const __m256 b[3], __m256 v[4]) {
  const __m256 s_f = _mm256_sub_ps(_mm256_sub_ps(full[3], middle[3]), back[3]);
  const __m256 specular = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(b[0], s_f), _mm256_mul_ps(b[1], middle[3])),
                                        _mm256_mul_ps(b[2], back[3]));
  for (int c = 0; c < 3; ++c) {
    const __m256 d_f = _mm256_sub_ps(_mm256_sub_ps(full[c], middle[c]), back[c]);
    v[c] = _mm256_add_ps(_mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(a[0], d_f), _mm256_mul_ps(a[1], middle[c])),
                                       _mm256_mul_ps(a[2], back[c])),
                         specular);
  }
  v[3] = full[3];
}
VRI_AVX2 void lit_interpolated8(const SecondOrderFloatLookup& table, const FloatLighting& lighting,
                                const Lanes<2>& L, __m256 v[4]) {
  __m256 full[4], middle[4], back[4];
  blend8(table, lighting.weighted[0], L, full);
  blend8(table, lighting.weighted[1], L, middle);
  blend8(table, lighting.weighted[2], L, back);
  const __m256 a[3] = {load(L.ta[0]), load(L.ta[1]), load(L.ta[2])}, b[3] = {load(L.tb[0]), load(L.tb[1]), load(L.tb[2])};
  lagrange8(full, middle, back, a, b, v);
}

// lit_by of 8 lanes: the colour v lit by the terms (a, b).
VRI_AVX2 void lit_by8(__m256 a, __m256 b, __m256 v[4]) {
  for (int c = 0; c < 3; ++c) v[c] = _mm256_add_ps(_mm256_mul_ps(v[c], a), _mm256_mul_ps(b, v[3]));
}

// A lit sample's state: its gradient (`sampled`) or its shading terms
// (`interpolated`), into the lanes of `m`.
VRI_AVX2 void lit_sample(const FloatLighting& lighting, const Cells8& cells, const __m256 d[3], __m256 m,
                         __m256 keep_g[3], __m256& keep_a, __m256& keep_b) {
  __m256 g[3];
  gradient8(*lighting.shading, cells, g);
  if (lighting.interpolated()) {
    __m256 a, b;
    terms8(*lighting.shading, g, d, a, b);
    keep_a = _mm256_blendv_ps(keep_a, a, m);
    keep_b = _mm256_blendv_ps(keep_b, b, m);
  } else {
    for (int c = 0; c < 3; ++c) keep_g[c] = _mm256_blendv_ps(keep_g[c], g[c], m);
  }
}

// Slab k of the lanes in `bits` found anew, at a ray's entry or after a
// leap: its samples k Steps .. (k + 1) Steps and its spot.
template <int Steps, class T>
VRI_AVX2 void start_slab(const FloatSampler& sampler, const T* values, const FloatLighting& lighting,
                         const TableAxis8& axis, int n, Lanes<Steps>& L, unsigned bits) {
  const __m256 m = lane_mask(bits);
  const __m256i first = _mm256_mullo_epi32(load(L.k), _mm256_set1_epi32(Steps));
  __m256i i[Steps + 1];
  for (int j = 0; j <= Steps; ++j) {
    Cells8 cells;
    const __m256 s = sample8(sampler, values, L, _mm256_add_epi32(first, _mm256_set1_epi32(j)), &cells);
    if (lighting.shading) {
      __m256 g[3] = {load(L.grad[j][0]), load(L.grad[j][1]), load(L.grad[j][2])}, a = load(L.ta[j]), b = load(L.tb[j]);
      const __m256 d[3] = {load(L.d[0]), load(L.d[1]), load(L.d[2])};
      lit_sample(lighting, cells, d, m, g, a, b);
      for (int c = 0; c < 3; ++c) store(L.grad[j][c], g[c]);
      store(L.ta[j], a), store(L.tb[j], b);
    }
    __m256 w;
    place8(axis, s, i[j], w);
    store(L.s[j], _mm256_blendv_ps(load(L.s[j]), s, m));
    store(L.w[j], _mm256_blendv_ps(load(L.w[j]), w, m));
    store(L.i[j], blend(load(L.i[j]), i[j], m));
  }
  store(L.entry, blend(load(L.entry), spot8<Steps>(i, _mm256_set1_epi32(n)), m));
}

}  // namespace vri::detail::lanes8
