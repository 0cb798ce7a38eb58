#include "tables/second_order_fast.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "vri/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/simd.hpp"
#include "tables/incremental_builder.hpp"
#include "tables/table_builder.hpp"
#include "tables/weighted_tables.hpp"

namespace vri {

namespace {

constexpr int kLanes = 8;
using F8 = float __attribute__((vector_size(4 * kLanes)));

// Channels of a first-order table laid out by diagonal: at(c, e, x) is
// channel c of entry (clamp(x), clamp(x + e)), clamp to [0, N-1], so that
// entries x .. x+7 of one diagonal e are 8 consecutive floats. x and x + e
// run over [-pad, N - 1 + pad]: the padding is the clamping of SPEC §3 (a
// parabola through three values in [lo, hi] stays within 1/8 of hi - lo of
// them), widened for the lanes past a row's last entry, whose values are
// computed and dropped.
struct DiagonalLayout {
  int pad = 0, width = 0, e_max = 0;
  std::vector<std::vector<float>> channel;
  std::size_t index(int e, int x) const { return static_cast<std::size_t>(e + e_max) * width + (x + pad); }
  const float* at(int c, int e, int x) const { return channel[c].data() + index(e, x); }
};

// value(f, b, c): channel c of entry (f, b).
template <class Value>
DiagonalLayout lay_out(int n, int channels, Value value) {
  DiagonalLayout d;
  d.pad = (n + 2 * kLanes) / 8 + 2 + kLanes;
  d.width = n + 2 * d.pad + 1;  // the +1: a bilinear corner past the last end
  d.e_max = d.width;
  d.channel.assign(channels, std::vector<float>(static_cast<std::size_t>(2 * d.e_max + 1) * d.width));
  tbb::parallel_for(-d.e_max, d.e_max + 1, [&](int e) {
    for (int x = -d.pad; x < d.width - d.pad; ++x) {
      const int f = std::clamp(x, 0, n - 1), b = std::clamp(x + e, 0, n - 1);
      for (int c = 0; c < channels; ++c) d.channel[c][d.index(e, x)] = value(f, b, c);
    }
  });
  return d;
}

// The chords of every entry of the diagonals (d1, d2) = (m - f, b - f) of one
// d1: with q(t) = (A t + B) t, A = 2 d2 - 4 d1, B = 4 d1 - d2, the parabola
// of entry f is q(t) + f, so chord end j sits at table index index(d2, j) + f
// + w_j for every f. corner(d2, k) are chord k's bilinear weights
// (1-wa)(1-wb), wa(1-wb), (1-wa)wb, wa wb of its front (a) and back (b) end.
class DiagonalChords {
 public:
  DiagonalChords(int n, int d1, int iterations)
      : n_(n), k_(iterations), index_((2 * n - 1) * (k_ + 1)), corner_((2 * n - 1) * 4 * k_) {
    std::vector<double> w(k_ + 1);
    for (int d2 = -(n - 1); d2 < n; ++d2) {
      const double A = 2.0 * d2 - 4.0 * d1, B = 4.0 * d1 - d2;
      int* index = &index_[(d2 + n - 1) * (k_ + 1)];
      for (int j = 0; j <= k_; ++j) {
        const double t = double(j) / k_, q = (A * t + B) * t, q0 = std::floor(q);
        index[j] = static_cast<int>(q0);
        w[j] = q - q0;
      }
      float* corner = &corner_[(d2 + n - 1) * 4 * k_];
      for (int k = 0; k < k_; ++k) {
        const double wa = w[k], wb = w[k + 1];
        const double c[4] = {(1 - wa) * (1 - wb), wa * (1 - wb), (1 - wa) * wb, wa * wb};
        for (int i = 0; i < 4; ++i) corner[4 * k + i] = static_cast<float>(c[i]);
      }
    }
  }
  const int* index(int d2) const { return &index_[(d2 + n_ - 1) * (k_ + 1)]; }
  const float* corner(int d2) const { return &corner_[(d2 + n_ - 1) * 4 * k_]; }

 private:
  int n_, k_;
  std::vector<int> index_;
  std::vector<float> corner_;
};

// What chords_lanes returns per lane: the entry (rgb, alpha) and, with
// weights, weighted[w] = (D.rgb, S) for the middle (w = 0) and back (w = 1)
// Lagrange weight.
struct LaneResults {
  float rgba[4][kLanes];
  float weighted[2][4][kLanes];
};

// The Lagrange weights at the chord ends t_j = j / K (second_order_weighted.hpp).
struct ChordEndWeights {
  std::vector<float> middle, back;
};

ChordEndWeights chord_end_weights(int iterations) {
  ChordEndWeights w;
  for (int j = 0; j <= iterations; ++j) {
    const double t = double(j) / iterations;
    w.middle.push_back(static_cast<float>(lagrange_middle(t)));
    w.back.push_back(static_cast<float>(lagrange_back(t)));
  }
  return w;
}

// The SIMD primitive: the entries f0 .. f0+7 of one diagonal (lanes) through
// their K chords, each chord a bilinear lookup of the first-order table
// `full` (and, Weighted, of the weighted tables `w`: channels D_front.rgb,
// D_back.rgb, S_back) at its two ends, composited front to back. A Lagrange
// weight, linear across a chord, weighs its front-weighted part by L(t_k) and
// its back-weighted part by L(t_{k+1}). The unweighted sums are the same
// operations with or without weights (the same bytes). Vectors live only
// inside this function (no vector arguments or results, so no ABI
// differences between the clones).
template <bool Weighted>
__attribute__((always_inline)) inline void chords_lanes_impl(const DiagonalLayout& full, const DiagonalLayout* w,
                                                             const int* index, const float* corner,
                                                             const ChordEndWeights* lagrange, int f0, int iterations,
                                                             LaneResults& out) {
  // acc += w * (8 floats at p).
  const auto add = [](F8& acc, float w, const float* p) {
    F8 v;
    std::memcpy(&v, p, sizeof(F8));
    acc += w * v;
  };
  F8 T = F8{} + 1.0f, C[3] = {};
  F8 W[2][4] = {};
  for (int k = 0; k < iterations; ++k) {
    const int a = index[k] + f0, e = index[k + 1] - index[k];
    const float* cw = &corner[4 * k];
    // r = channel c of entry (a + wa, a + e + wb).
    const auto lookup = [&](const DiagonalLayout& t, int c, F8& r) {
      r = F8{};
      add(r, cw[0], t.at(c, e, a)), add(r, cw[1], t.at(c, e - 1, a + 1));
      add(r, cw[2], t.at(c, e + 1, a)), add(r, cw[3], t.at(c, e, a + 1));
    };
    F8 alpha;
    lookup(full, 3, alpha);
    if constexpr (Weighted) {
      const float weight[2][2] = {{lagrange->middle[k], lagrange->middle[k + 1]},
                                  {lagrange->back[k], lagrange->back[k + 1]}};
      F8 front[4], back[4];
      for (int c = 0; c < 3; ++c) lookup(*w, c, front[c]), lookup(*w, 3 + c, back[c]);
      lookup(*w, 6, back[3]);
      front[3] = alpha - back[3];
      for (int q = 0; q < 2; ++q)
        for (int c = 0; c < 4; ++c) W[q][c] += T * (weight[q][0] * front[c] + weight[q][1] * back[c]);
    }
    for (int c = 0; c < 3; ++c) {
      F8 colour;
      lookup(full, c, colour);
      C[c] += T * colour;
    }
    T *= 1.0f - alpha;
  }
  for (int j = 0; j < kLanes; ++j) {
    for (int c = 0; c < 3; ++c) out.rgba[c][j] = C[c][j];
    out.rgba[3][j] = 1.0f - T[j];
    if constexpr (Weighted)
      for (int q = 0; q < 2; ++q)
        for (int c = 0; c < 4; ++c) out.weighted[q][c][j] = W[q][c][j];
  }
}

VRI_TARGET_CLONES __attribute__((flatten)) void chords_lanes(const DiagonalLayout& full, const int* index,
                                                             const float* corner, int f0, int iterations,
                                                             LaneResults& out) {
  chords_lanes_impl<false>(full, nullptr, index, corner, nullptr, f0, iterations, out);
}

VRI_TARGET_CLONES __attribute__((flatten)) void chords_lanes_weighted(const DiagonalLayout& full,
                                                                      const DiagonalLayout& w, const int* index,
                                                                      const float* corner,
                                                                      const ChordEndWeights& lagrange, int f0,
                                                                      int iterations, LaneResults& out) {
  chords_lanes_impl<true>(full, &w, index, corner, &lagrange, f0, iterations, out);
}

void store(float* e, const LaneResults& r, int lane) {
  for (int c = 0; c < 4; ++c) e[c] = r.rgba[c][lane];
}

void store_weighted(float* e, const LaneResults& r, int weight, int lane) {
  for (int c = 0; c < 4; ++c) e[c] = r.weighted[weight][c][lane];
}

// The first-order table of the chords (length L/K; the incremental builder,
// which integrates control points inside a bin) laid out by diagonal.
DiagonalLayout chord_table(const DiscreteTf& tf, double chord_length) {
  const PreintegrationTable t = IncrementalBuilder().build(tf, chord_length);
  return lay_out(tf.size(), 4, [&](int f, int b, int c) { return t.entry(f, b)[c]; });
}

// Its weighted tables (weighted_tables.hpp), as D_front.rgb, D_back.rgb, S_back.
DiagonalLayout weighted_chord_tables(const DiscreteTf& tf, double chord_length) {
  const WeightedTables t = build_weighted_tables(tf, chord_length);
  return lay_out(tf.size(), 7,
                 [&](int f, int b, int c) { return c < 3 ? t.front.entry(f, b)[c] : t.back.entry(f, b)[c - 3]; });
}

// Computes every entry and hands it to store(f, m, b, lane, results). One
// task per d1 = m - f; in it, 8 consecutive f (lanes) walk all d2 = b - f, so
// that each lane writes its row (f, m, .) in order.
template <bool Weighted, class Store>
void walk_entries(const DiscreteTf& tf, double length, int iterations, Store&& store_entry) {
  const int n = tf.size();
  const DiagonalLayout full = chord_table(tf, length / iterations);
  const DiagonalLayout weighted = Weighted ? weighted_chord_tables(tf, length / iterations) : DiagonalLayout{};
  const ChordEndWeights lagrange = Weighted ? chord_end_weights(iterations) : ChordEndWeights{};
  // Every entry is computed by the same lanes code whatever the partition,
  // so the bytes do not depend on the thread count.
  tbb::parallel_for(-(n - 1), n, [&](int d1) {
    const DiagonalChords chords(n, d1, iterations);
    LaneResults out;
    const int f_lo = std::max(0, -d1), f_hi = std::min(n - 1, n - 1 - d1);
    for (int f0 = f_lo; f0 <= f_hi; f0 += kLanes) {
      for (int d2 = std::max(-(n - 1), -(f0 + kLanes - 1)); d2 <= n - 1 - f0; ++d2) {
        // A task is up to n^2 x iterations chord steps (seconds): a cancelled
        // build (a viewer page gone, Ctrl-C in Python) stops here, not at its end.
        if (tbb::is_current_task_group_canceling()) return;
        if constexpr (Weighted)
          chords_lanes_weighted(full, weighted, chords.index(d2), chords.corner(d2), lagrange, f0, iterations, out);
        else
          chords_lanes(full, chords.index(d2), chords.corner(d2), f0, iterations, out);
        for (int j = 0; j < kLanes; ++j) {
          const int f = f0 + j, b = f + d2;
          if (f <= f_hi && b >= 0 && b < n) store_entry(f, f + d1, b, j, out);
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
  walk_entries<false>(tf, length, iterations, [&](int f, int m, int b, int j, const LaneResults& out) {
    store(table.entry(f, m, b), out, j);
  });
  throw_if_build_cancelled();
  write_straight_entries(tf, table);
  return table;
}

SecondOrderWeightedTables FastSecondOrderBuilder::build_weighted(const DiscreteTf& tf, double length,
                                                                 int iterations) const {
  check_slab_length(length);
  check_iterations(iterations);
  SecondOrderWeightedTables t(tf.axis(), length, iterations);
  walk_entries<true>(tf, length, iterations, [&](int f, int m, int b, int j, const LaneResults& out) {
    store(t.full.entry(f, m, b), out, j);
    store_weighted(t.middle.entry(f, m, b), out, 0, j);
    store_weighted(t.back.entry(f, m, b), out, 1, j);
  });
  throw_if_build_cancelled();
  // The straight entries as build() writes them, and their weighted parts
  // from the same definition.
  write_straight_entries(tf, t.full);
  const int n = tf.size();
  tbb::parallel_for(0, n, [&](int f) {
    for (int b = f % 2; b < n; b += 2) {
      const SecondOrderWeights w = second_order_weighted_entry(tf, f, (f + b) / 2, b, length, iterations);
      store(t.middle.entry(f, (f + b) / 2, b), w.middle);
      store(t.back.entry(f, (f + b) / 2, b), w.back);
    }
  });
  throw_if_build_cancelled();
  return t;
}

}  // namespace vri
