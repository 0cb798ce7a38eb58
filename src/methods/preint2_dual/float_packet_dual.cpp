// preint2-dual's float path on packets of 8 rays (float_packet.hpp): each
// lane walks its own cells, one segment per lane and iteration, with
// march_cells_float's operations (dual_march.hpp) in the same order. The cell
// walk (for_each_cell_segment's, in double), the samples, their places on the
// table axis, the length bracket, the two length slices' lookups and the
// shading (float_shading.hpp, both modes) and the compositing run on the 8
// lanes as vectors; the skipping and termination tests, as cheap as they are
// branchy, per lane. The same bytes, ray by ray.
#include "core/simd.hpp"
#if VRI_HAVE_AVX2_PACKETS
#include <optional>

#include "dual_march.hpp"
#include "methods/march/packet_lanes.hpp"

namespace vri::detail {

using namespace lanes8;

namespace {

// What for_each_cell_segment keeps per ray, a lane each, and the lanes'
// current segment [ta, tb] (cell, local position at ta, length).
struct DualLanes : Composited8 {
  alignas(32) double u0[3][kPacket], du[3][kPacket], dir[3][kPacket], plane[3][kPacket], t_next[3][kPacket];
  alignas(32) double ta[kPacket], tb[kPacket], t1[kPacket];
  alignas(32) double local0[3][kPacket], length[kPacket];
  alignas(32) int cell[3][kPacket];
  alignas(32) float d[3][kPacket];  // the direction, for lighting
};

// One step of for_each_cell_segment's loop for lanes 4 half .. 4 half + 3:
// tb, the planes passed, and the segment's cell and local position (kept
// for every lane; only those with tb > ta use them).
VRI_AVX2 void walk_step(DualLanes& L, int half, const int (&last)[3]) {
  const int o = 4 * half;
  const __m256d ta = _mm256_load_pd(L.ta + o);
  __m256d tb = _mm256_load_pd(L.t1 + o);
  for (int a = 2; a >= 0; --a) tb = _mm256_min_pd(_mm256_load_pd(L.t_next[a] + o), tb);
  _mm256_store_pd(L.tb + o, tb);
  for (int a = 0; a < 3; ++a) {
    const __m256d u0 = _mm256_load_pd(L.u0[a] + o), du = _mm256_load_pd(L.du[a] + o), dir = _mm256_load_pd(L.dir[a] + o);
    const __m256d moving = _mm256_cmp_pd(dir, _mm256_setzero_pd(), _CMP_NEQ_OQ);
    __m256d plane = _mm256_load_pd(L.plane[a] + o), t_next = _mm256_load_pd(L.t_next[a] + o);
    for (__m256d passed; _mm256_movemask_pd(passed = _mm256_and_pd(moving, _mm256_cmp_pd(t_next, tb, _CMP_LE_OQ)));) {
      plane = _mm256_blendv_pd(plane, _mm256_add_pd(plane, dir), passed);
      t_next = _mm256_blendv_pd(t_next, _mm256_div_pd(_mm256_sub_pd(plane, u0), du), passed);
    }
    _mm256_store_pd(L.plane[a] + o, plane);
    _mm256_store_pd(L.t_next[a] + o, t_next);
    const __m256d tm = _mm256_mul_pd(_mm256_set1_pd(0.5), _mm256_add_pd(ta, tb));
    const __m256d um = _mm256_floor_pd(_mm256_add_pd(u0, _mm256_mul_pd(du, tm)));
    const __m128i cell =
        _mm256_cvttpd_epi32(_mm256_min_pd(_mm256_set1_pd(last[a]), _mm256_max_pd(_mm256_setzero_pd(), um)));
    _mm_store_si128(reinterpret_cast<__m128i*>(L.cell[a] + o), cell);
    _mm256_store_pd(L.local0[a] + o, _mm256_sub_pd(_mm256_add_pd(u0, _mm256_mul_pd(du, ta)), _mm256_cvtepi32_pd(cell)));
  }
  _mm256_store_pd(L.length + o, _mm256_sub_pd(tb, ta));
}

// march_cells_float's cell_at(dt) on one axis, for dt = scale * length
// (scale 0, 1/2 or 1): the float fraction in the cell, clamped to [0, 1].
VRI_AVX2 __m256 fraction8(const DualLanes& L, int a, double scale) {
  __m128 f[2];
  for (int half = 0; half < 2; ++half) {
    const int o = 4 * half;
    const __m256d len = _mm256_load_pd(L.length + o);
    const __m256d dt = scale == 1 ? len : _mm256_mul_pd(_mm256_set1_pd(scale), len);
    f[half] = _mm256_cvtpd_ps(
        _mm256_add_pd(_mm256_load_pd(L.local0[a] + o), _mm256_mul_pd(dt, _mm256_load_pd(L.du[a] + o))));
  }
  return _mm256_min_ps(_mm256_set1_ps(1), _mm256_max_ps(_mm256_setzero_ps(), _mm256_set_m128(f[1], f[0])));
}

// Lane l's walk, standing at the end of a skipped segment, moved to where the
// scalar walk stands after the segments that end by x (all in an empty run,
// so skipped too). For each axis: the last plane crossed by x, found from an
// estimate and the walk's own crossing formula (plane - u0) / du, whose
// values are monotone in the plane. The walk then starts at the latest of
// those crossings with the next plane on each axis ahead, as the scalar walk
// does after its segment ending there: the same segments follow, without
// walking the cells between.
void leap_to(DualLanes& L, int l, double x) {
  double ta = L.tb[l];  // the walk has passed the skipped segment's planes already
  for (int a = 0; a < 3; ++a) {
    const double u0 = L.u0[a][l], du = L.du[a][l], dir = L.dir[a][l];
    const auto crossing = [&](double plane) { return (plane - u0) / du; };
    if (dir == 0 || crossing(L.plane[a][l]) > x) continue;  // no plane of this axis by x
    const double ux = u0 + du * x;
    double q = dir > 0 ? std::floor(ux) : std::ceil(ux);  // the last plane by x, near enough
    while (crossing(q) > x) q -= dir;
    while (crossing(q + dir) <= x) q += dir;
    ta = std::max(ta, crossing(q));
    L.plane[a][l] = q + dir;
    L.t_next[a][l] = crossing(q + dir);
  }
  L.ta[l] = ta;
}

// The spots' rows in both slices of table 0 (DualFloatLookup::find's
// prefetches), for the 8 lanes: asked for all at once, their loads overlap.
// None for a spot of zeros, which the blend does not read.
VRI_AVX2 void prefetch8(const DualFloatLookup& table, const int* slice, const int* first) {
  for (int l = 0; l < kPacket; ++l) {
    if (table.zero(first[l])) continue;
    table.slice(slice[l]).prefetch(first[l]);
    table.slice(slice[l] + 1).prefetch(first[l]);
  }
}

// DualFloatLookup::blend of table k for the 8 lanes, lane by lane in its
// order: each row's two entries (b, b + 1) as one 8-float vector, the
// slices blended first (wl), then s_m, s_f, and s_b across the vector's
// halves; the lanes' results transposed into channels at the end. A spot of
// zeros gives +0, unread, as DualFloatLookup::blend.
VRI_AVX2 void dual_blend8(const DualFloatLookup& table, int k, const int* slice, const int* first,
                          const float (&w)[4][kPacket], __m256 v[4]) {
  const std::size_t row = table.row(), plane = table.plane();
  __m128 e[kPacket];
  for (int l = 0; l < kPacket; ++l) {
    if (table.zero(first[l])) {
      e[l] = _mm_setzero_ps();
      continue;
    }
    const float *lo = table.data(slice[l], k) + first[l], *hi = table.data(slice[l] + 1, k) + first[l];
    const __m256 wl = _mm256_broadcast_ss(w[0] + l), wf = _mm256_broadcast_ss(w[1] + l),
                 wm = _mm256_broadcast_ss(w[2] + l);
    __m256 r[2][2];
    for (int f = 0; f < 2; ++f)
      for (int m = 0; m < 2; ++m) {
        const std::size_t add = f * plane + m * row;
        r[f][m] = lerp(_mm256_loadu_ps(lo + add), _mm256_loadu_ps(hi + add), wl);
      }
    const __m256 p = lerp(lerp(r[0][0], r[0][1], wm), lerp(r[1][0], r[1][1], wm), wf);
    const __m128 b0 = _mm256_castps256_ps128(p), b1 = _mm256_extractf128_ps(p, 1);
    e[l] = _mm_add_ps(b0, _mm_mul_ps(_mm_broadcast_ss(w[3] + l), _mm_sub_ps(b1, b0)));
  }
  __m256 q[4];
  for (int l = 0; l < 4; ++l) q[l] = _mm256_set_m128(e[l + 4], e[l]);
  transpose8(q, v);
}

template <class Value>
__attribute__((target("avx2"))) void march_dual(const GridVolume& volume, const Value* values,
                                                const DualFloatLookup& table, const FloatShading* shading,
                                                bool interpolated, const Ray* rays, const Leap& leap, Rgba* out) {
  const auto& n = volume.dims();
  const int last[3] = {n[0] - 2, n[1] - 2, n[2] - 2};
  const int sy = n[0], sz = n[0] * n[1];
  DualLanes L{};
  std::optional<SegmentSkip> skip[kPacket];
  unsigned active = 0;
  const auto finish = [&](int l) {
    out[l] = L.pixel(l);
    active &= ~(1u << l);
  };
  // for_each_cell_segment's set-up (cell_walk_axis), lane by lane; lanes
  // without a ray keep ta = t1 = 0 and are never active.
  for (int l = 0; l < kPacket; ++l) {
    const Ray& ray = rays[l];
    const auto whole = volume.clip(ray);
    if (!whole) {
      out[l] = {0, 0, 0, 0};
      continue;
    }
    const Interval iv = owned_part(*whole);  // all of it unless a brick (GridVolume::Brick)
    for (int a = 0; a < 3; ++a) {
      const CellWalkAxis w = cell_walk_axis(volume, ray, iv.t0, a);
      L.u0[a][l] = w.u0, L.du[a][l] = w.du, L.dir[a][l] = w.dir, L.plane[a][l] = w.plane, L.t_next[a][l] = w.t_next;
    }
    L.ta[l] = iv.t0, L.t1[l] = iv.t1, L.T[l] = 1;
    const FloatShading::Vector d = direction(ray);
    for (int a = 0; a < 3; ++a) L.d[a][l] = d[a];
    skip[l].emplace(leap, ray, iv.t1);
    active |= 1u << l;
    if (!(L.ta[l] < L.t1[l])) finish(l);
  }
  const SecondOrderFloatLookup& slice0 = table.slice(0);
  const TableAxis8 axis = axis8(slice0.axis());
  const __m256i entries = _mm256_set1_epi32(slice0.size());
  const __m256d max_length = _mm256_set1_pd(table.max_length()), top_slice = _mm256_set1_pd(table.lengths() - 1);
  while (active) {
    walk_step(L, 0, last);
    walk_step(L, 1, last);
    // Per lane, as the scalar march's visit: stop below the termination, then
    // leave out a skipped segment; every lane moves on to tb.
    unsigned sampled = 0, ended = 0;
    for (unsigned m = active; m; m &= m - 1) {
      const int l = __builtin_ctz(m);
      if (L.tb[l] > L.ta[l]) {
        if (L.T[l] < leap.termination) {
          finish(l);
          continue;
        }
        if (skip[l]->skipped(L.ta[l], L.tb[l])) {
          // Past the empty run at once (its segments all add nothing).
          if (const double x = skip[l]->empty_until(); x < L.t1[l]) {
            leap_to(L, l, x);
          } else {
            ended |= 1u << l;
          }
          continue;
        }
        // A transparent cell's segment adds nothing either: not sampled.
        if (!leap.cells || !leap.cells->transparent(L.cell[0][l], L.cell[1][l], L.cell[2][l])) sampled |= 1u << l;
      }
      L.ta[l] = L.tb[l];
      if (!(L.ta[l] < L.t1[l])) ended |= 1u << l;
    }
    if (sampled) {
      const __m256 m = lane_mask(sampled);
      // The cell's first corner (0 in lanes not sampled: a valid read).
      __m256i index = _mm256_add_epi32(
          load(L.cell[0]), _mm256_add_epi32(_mm256_mullo_epi32(load(L.cell[1]), _mm256_set1_epi32(sy)),
                                            _mm256_mullo_epi32(load(L.cell[2]), _mm256_set1_epi32(sz))));
      index = _mm256_castps_si256(_mm256_and_ps(_mm256_castsi256_ps(index), m));
      __m256 lo[4], hi[4];  // the corner pairs along x at (y, z) = (0, 0), (1, 0), (0, 1), (1, 1)
      corner_pairs8(values, index, sy, sz, lo, hi);
      // The front, middle and back samples, their places on the table axis
      // and, lit, their gradients.
      __m256i i[3];
      __m256 w[3];
      Cells8 cells[3];
      const double scale[3] = {0, 0.5, 1};
      for (int k = 0; k < 3; ++k) {
        const Cells8& cell = cells[k] = {index, fraction8(L, 0, scale[k]), fraction8(L, 1, scale[k]),
                                         fraction8(L, 2, scale[k])};
        const __m256 s = lerp(lerp(lerp(lo[0], hi[0], cell.fx), lerp(lo[1], hi[1], cell.fx), cell.fy),
                              lerp(lerp(lo[2], hi[2], cell.fx), lerp(lo[3], hi[3], cell.fx), cell.fy), cell.fz);
        place8(axis, s, i[k], w[k]);
      }
      const __m256i entry = spot8<2>(i, entries);
      // length_bracket: slices j and j + 1, weight wl.
      __m128i j[2];
      __m128 wl[2];
      for (int half = 0; half < 2; ++half) {
        const __m256d x = _mm256_div_pd(_mm256_load_pd(L.length + 4 * half), max_length);
        const __m256d u =
            _mm256_mul_pd(_mm256_min_pd(_mm256_set1_pd(1), _mm256_max_pd(_mm256_setzero_pd(), x)), top_slice);
        j[half] = _mm_min_epi32(_mm256_cvttpd_epi32(u), _mm_set1_epi32(table.lengths() - 2));
        wl[half] = _mm256_cvtpd_ps(_mm256_sub_pd(u, _mm256_cvtepi32_pd(j[half])));
      }
      alignas(32) int slice[kPacket], first[kPacket];
      store(slice, _mm256_castps_si256(_mm256_and_ps(_mm256_castsi256_ps(_mm256_set_m128i(j[1], j[0])), m)));
      store(first, _mm256_castps_si256(_mm256_and_ps(_mm256_castsi256_ps(entry), m)));
      prefetch8(table, slice, first);
      alignas(32) float weight[4][kPacket];  // wl, wf, wm, wb
      store(weight[0], _mm256_set_m128(wl[1], wl[0]));
      for (int k = 0; k < 3; ++k) store(weight[k + 1], w[k]);
      // Lit, the gradients at the three samples, while the entries load.
      __m256 grad[3][3];  // (read only when lit: not cleared for every segment)
      if (shading)
        for (int k = 0; k < 3; ++k) gradient8(*shading, cells[k], grad[k]);
      __m256 e[4];
      const __m256 d[3] = {load(L.d[0]), load(L.d[1]), load(L.d[2])};
      if (!shading) {
        dual_blend8(table, 0, slice, first, weight, e);
      } else if (!interpolated) {  // one normal, the mean of the three gradients
        dual_blend8(table, 0, slice, first, weight, e);
        __m256 mean[3], a, b;
        for (int c = 0; c < 3; ++c)
          mean[c] = _mm256_mul_ps(_mm256_add_ps(_mm256_add_ps(grad[0][c], grad[1][c]), grad[2][c]),
                                  _mm256_set1_ps(1.0f / 3));
        terms8(*shading, mean, d, a, b);
        lit_by8(a, b, e);
      } else {
        __m256 full[4], middle[4], back[4], a[3], b[3];
        dual_blend8(table, 0, slice, first, weight, full);
        dual_blend8(table, 1, slice, first, weight, middle);
        dual_blend8(table, 2, slice, first, weight, back);
        for (int k = 0; k < 3; ++k) terms8(*shading, grad[k], d, a[k], b[k]);
        lagrange8(full, middle, back, a, b, e);
      }
      // Lanes not sampled composite zeros: C + T 0 = C and T (1 - 0) = T exactly.
      for (__m256& x : e) x = _mm256_and_ps(x, m);
      composite8(L, e);
    }
    for (unsigned m = ended & active; m; m &= m - 1) finish(__builtin_ctz(m));
  }
}

}  // namespace

void march_dual_packet(const GridVolume& volume, const DualFloatLookup& table, const FloatShading* shading,
                       bool interpolated, const Ray* rays, const Leap& leap, Rgba* out) {
  volume.visit([&](auto values) { march_dual(volume, values.data(), table, shading, interpolated, rays, leap, out); });
}

}  // namespace vri::detail
#endif  // VRI_HAVE_AVX2_PACKETS
