#include "vri/tables/second_order_fast.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "core/simd.hpp"
#include "vri/tables/table_builder.hpp"

namespace vri {

namespace {

constexpr int kLanes = 8;
using F8 = float __attribute__((vector_size(4 * kLanes)));
using I8 = std::int32_t __attribute__((vector_size(4 * kLanes)));

// The transfer function per table scalar, padded on both sides with its end
// values: value[j] and slope[j] = value[j+1] - value[j] for j = i + pad.
// depth is tau * L/K, the optical depth of one sub-step.
struct PaddedTf {
  int pad = 0;
  std::vector<float> value[4], slope[4];  // depth, r, g, b
};

PaddedTf pad_tf(const DiscreteTf& tf, double step) {
  const int n = tf.size();
  PaddedTf p;
  p.pad = (n - 1) / 8 + 2;
  const int total = n + 2 * p.pad + kLanes;
  for (int c = 0; c < 4; ++c) p.value[c].resize(total), p.slope[c].resize(total);
  for (int j = 0; j < total; ++j) {
    const TfSample& s = tf[std::clamp(j - p.pad, 0, n - 1)];
    const double v[4] = {s.tau * step, s.r, s.g, s.b};
    for (int c = 0; c < 4; ++c) p.value[c][j] = static_cast<float>(v[c]);
  }
  for (int c = 0; c < 4; ++c)
    for (int j = 0; j + 1 < total; ++j) p.slope[c][j] = p.value[c][j + 1] - p.value[c][j];
  return p;
}

// What composite_lanes returns per lane: the colour seen from the front
// (rgb[0..2]), from the back (rgb[3..5]) and alpha (the same both ways); with
// weights, weighted[v][w] = (D.rgb, S) of view v (0 front, 1 back) for that
// view's middle (w = 0) and back (w = 1) Lagrange weight.
struct LaneResults {
  float rgb[6][kLanes];
  float alpha[kLanes];
  float weighted[2][2][4][kLanes];
};

// The Lagrange weights at the sub-step midpoints t_k (second_order_weighted.hpp):
// front[k] = L_f(t_k), middle[k] = L_m(t_k), back[k] = L_b(t_k).
struct SubstepWeights {
  std::vector<float> front, middle, back;
};

SubstepWeights substep_weights(int iterations) {
  SubstepWeights w;
  for (int k = 0; k < iterations; ++k) {
    const double t = (k + 0.5) / iterations;
    w.front.push_back(static_cast<float>(lagrange_front(t)));
    w.middle.push_back(static_cast<float>(lagrange_middle(t)));
    w.back.push_back(static_cast<float>(lagrange_back(t)));
  }
  return w;
}

// The SIMD primitive: 8 entries (lanes) through K sub-steps. Sub-step k of
// lane j samples the padded arrays at index[k] + j with weight weight[k].
// The same samples read backwards are the entry (s_b, s_m, s_f), so the
// reverse colour is accumulated too ("under": C = c_k a_k + (1 - a_k) C),
// which halves the work. Read backwards, u becomes 1 - u: the back view's
// middle weight is L_m(t_k), its back weight L_f(t_k). The unweighted sums
// are the same operations with or without weights (the same bytes). Vectors
// live only inside this function (no vector arguments, so no ABI differences
// between the clones).
template <bool Weighted>
__attribute__((always_inline)) inline void composite_lanes_impl(const PaddedTf& tf, const int* index,
                                                                const float* weight, const SubstepWeights* lagrange,
                                                                int iterations, LaneResults& out) {
  F8 T = F8{} + 1.0f, C[6] = {};
  F8 W[2][2][4] = {};
  for (int k = 0; k < iterations; ++k) {
    const int i = index[k];
    const float w = weight[k];
    F8 v[4];
    for (int c = 0; c < 4; ++c) {
      F8 value, slope;
      std::memcpy(&value, &tf.value[c][i], sizeof(F8));
      std::memcpy(&slope, &tf.slope[c][i], sizeof(F8));
      v[c] = value + w * slope;
    }
    // e = exp(-depth) (Cephes expf): exp(x) = 2^n exp(r), r = x - n ln 2.
    const F8 x = -(v[0] < 87.0f ? v[0] : F8{} + 87.0f);
    const I8 n = -__builtin_convertvector(x * -1.44269504f + 0.5f, I8);
    const F8 nf = __builtin_convertvector(n, F8);
    const F8 r = x - nf * 0.693359375f + nf * 2.12194440e-4f;
    F8 p = F8{} + 1.9875691500e-4f;
    p = p * r + 1.3981999507e-3f;
    p = p * r + 8.3334519073e-3f;
    p = p * r + 4.1665795894e-2f;
    p = p * r + 1.6666665459e-1f;
    p = p * r + 5.0000001201e-1f;
    p = p * r * r + r + 1.0f;
    const I8 scale = (n + 127) << 23;
    F8 two_n;
    std::memcpy(&two_n, &scale, sizeof(F8));
    const F8 e = p * two_n, a = 1.0f - e;
    for (int c = 0; c < 3; ++c) {
      const F8 emitted = a * v[c + 1];
      C[c] += T * emitted;
      C[c + 3] = emitted + e * C[c + 3];
    }
    if constexpr (Weighted) {
      // Front view: weights (L_m, L_b) on T_k x; back view: (L_m, L_f) "under".
      const float front_view[2] = {lagrange->middle[k], lagrange->back[k]};
      const float back_view[2] = {lagrange->middle[k], lagrange->front[k]};
      for (int q = 0; q < 2; ++q) {
        const F8 Tw = T * front_view[q];
        for (int c = 0; c < 3; ++c) {
          const F8 emitted = a * v[c + 1];
          W[0][q][c] += Tw * emitted;
          W[1][q][c] = back_view[q] * emitted + e * W[1][q][c];
        }
        W[0][q][3] += Tw * a;
        W[1][q][3] = back_view[q] * a + e * W[1][q][3];
      }
    }
    T *= e;
  }
  for (int j = 0; j < kLanes; ++j) {
    for (int c = 0; c < 6; ++c) out.rgb[c][j] = C[c][j];
    out.alpha[j] = 1.0f - T[j];
    if constexpr (Weighted)
      for (int view = 0; view < 2; ++view)
        for (int q = 0; q < 2; ++q)
          for (int c = 0; c < 4; ++c) out.weighted[view][q][c][j] = W[view][q][c][j];
  }
}

VRI_TARGET_CLONES __attribute__((flatten)) void composite_lanes(const PaddedTf& tf, const int* index,
                                                                const float* weight, int iterations,
                                                                LaneResults& out) {
  composite_lanes_impl<false>(tf, index, weight, nullptr, iterations, out);
}

VRI_TARGET_CLONES __attribute__((flatten)) void composite_lanes_weighted(
    const PaddedTf& tf, const int* index, const float* weight, const SubstepWeights& lagrange, int iterations,
    LaneResults& out) {
  composite_lanes_impl<true>(tf, index, weight, &lagrange, iterations, out);
}

void store(float* e, const LaneResults& r, int first_channel, int lane) {
  for (int c = 0; c < 3; ++c) e[c] = r.rgb[first_channel + c][lane];
  e[3] = r.alpha[lane];
}

void store_weighted(float* e, const LaneResults& r, int view, int weight, int lane) {
  for (int c = 0; c < 4; ++c) e[c] = r.weighted[view][weight][c][lane];
}

// Walks every entry as build() describes and hands each to
// store(f, m, b, view, lane, results): view 0 is the entry (f, f + d1, f + d2)
// of lane f - f0, view 1 its reverse (f + d2, f + d1, f) when d2 > 0.
template <bool Weighted, class Store>
void walk_diagonals(const DiscreteTf& tf, double length, int iterations, Store&& store_entry) {
  const int n = tf.size();
  const PaddedTf padded = pad_tf(tf, length / iterations);
  const SubstepWeights lagrange = Weighted ? substep_weights(iterations) : SubstepWeights{};
  // One task per d1 = m - f; every entry is computed by the same lanes code
  // whatever the partition, so the bytes do not depend on the thread count.
  tbb::parallel_for(-(n - 1), n, [&](int d1) {
    std::vector<int> offset(iterations), index(iterations);
    std::vector<float> weight(iterations);
    LaneResults out;
    // d2 = b - f >= 0; the entries with b < f are these read backwards.
    for (int d2 = 0; d2 < n; ++d2) {
      const int f_lo = std::max({0, -d1, -d2}), f_hi = std::min({n - 1, n - 1 - d1, n - 1 - d2});
      if (f_lo > f_hi) continue;
      const double A = 2.0 * d2 - 4.0 * d1, B = 4.0 * d1 - d2;
      for (int k = 0; k < iterations; ++k) {
        const double t = (k + 0.5) / iterations;
        const double q = (A * t + B) * t;
        const double q0 = std::floor(q);
        offset[k] = static_cast<int>(q0) + padded.pad;
        weight[k] = static_cast<float>(q - q0);
      }
      for (int f0 = f_lo; f0 <= f_hi; f0 += kLanes) {
        for (int k = 0; k < iterations; ++k) index[k] = offset[k] + f0;
        if constexpr (Weighted)
          composite_lanes_weighted(padded, index.data(), weight.data(), lagrange, iterations, out);
        else
          composite_lanes(padded, index.data(), weight.data(), iterations, out);
        for (int j = 0; j < kLanes && f0 + j <= f_hi; ++j) {
          const int f = f0 + j;
          store_entry(f, f + d1, f + d2, 0, j, out);
          if (d2 > 0) store_entry(f + d2, f + d1, f, 1, j, out);
        }
      }
    }
  });
}

}  // namespace

SecondOrderTable FastSecondOrderBuilder::build(const DiscreteTf& tf, double length, int iterations) const {
  check_slab_length(length);
  check_iterations(iterations);
  SecondOrderTable table(tf.axis(), length, iterations);
  walk_diagonals<false>(tf, length, iterations, [&](int f, int m, int b, int view, int j, const LaneResults& out) {
    store(table.entry(f, m, b), out, 3 * view, j);
  });
  return table;
}

SecondOrderWeightedTables FastSecondOrderBuilder::build_weighted(const DiscreteTf& tf, double length,
                                                                 int iterations) const {
  check_slab_length(length);
  check_iterations(iterations);
  SecondOrderWeightedTables t(tf.axis(), length, iterations);
  walk_diagonals<true>(tf, length, iterations, [&](int f, int m, int b, int view, int j, const LaneResults& out) {
    store(t.full.entry(f, m, b), out, 3 * view, j);
    store_weighted(t.middle.entry(f, m, b), out, view, 0, j);
    store_weighted(t.back.entry(f, m, b), out, view, 1, j);
  });
  return t;
}

}  // namespace vri
