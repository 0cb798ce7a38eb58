#include "vri/tables/incremental_builder.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <vector>

#include "vri/tables/piece_weights.hpp"
#include "vri/tables/slab_integral.hpp"

namespace vri {

namespace {

using Entry = std::array<float, 4>;
using V2 = double __attribute__((vector_size(16)));

Entry to_entry(const SlabRgba& v) {
  return {static_cast<float>(v.r), static_cast<float>(v.g), static_cast<float>(v.b), static_cast<float>(v.a)};
}

// What every diagonal needs from the transfer function: per piece k (table
// scalars k, k+1) its end extinctions, and the pieces by decreasing
// extinction, so the pieces too thick for the series at piece length d are
// a prefix of `by_thickness`.
struct Pieces {
  std::vector<double> tau;         // tau[k] at table scalar k
  std::vector<int> by_thickness;   // piece indices, max(tau_k, tau_k+1) decreasing
  explicit Pieces(const DiscreteTf& tf) : tau(tf.size()), by_thickness(tf.size() - 1) {
    for (int k = 0; k < tf.size(); ++k) tau[k] = tf[k].tau;
    std::iota(by_thickness.begin(), by_thickness.end(), 0);
    std::stable_sort(by_thickness.begin(), by_thickness.end(),
                     [&](int a, int b) { return thickest(a) > thickest(b); });
  }
  double thickest(int k) const { return std::max(tau[k], tau[k + 1]); }
};

// Scratch of one thread. For diagonal m, piece k has length l/m; bins are
// pieces [b m, (b+1) m) (Lum et al. 2004, Fig. 5). Within each bin, for piece k:
//   head[k] = pieces bin_start..k   (left-hand subrange grown to the right)
//   tail[k] = pieces k..bin_end-1   (right-hand subrange grown to the left)
// forward (front = lower scalar) and backward (front = higher scalar).
struct Scratch {
  // Piece weights as separate arrays, so the series loop vectorises.
  std::vector<double> fp, fq, bq, bp, alpha;
  std::vector<SlabRgba> head_f, tail_f, head_b, tail_b;
  std::vector<Entry> upper, lower;  // kGroup diagonals, n entries each
};

// Diagonal m: upper[i] = entry (i, i+m), lower[i] = entry (i+m, i), i + m < n.
void build_diagonal(const DiscreteTf& tf, const Pieces& pieces, double length, int m, Scratch& s,
                    Entry* upper, Entry* lower) {
  const int n = tf.size(), count = n - 1;
  const double d = length / m;
  // The series for every piece (a branch-free loop), then the thick ones again.
  const auto set = [&s](int k, const PieceWeights& w) {
    s.fp[k] = w.fp, s.fq[k] = w.fq, s.bq[k] = w.bq, s.bp[k] = w.bp, s.alpha[k] = w.alpha;
  };
  const double* tau = pieces.tau.data();
  const auto thin = [d](double t) { return std::min(t * d, piece_series::kThin); };
  int k = 0;
  for (; k + 1 < count; k += 2) {  // two pieces per SSE2 register
    const auto w = thin_piece_weights(V2{thin(tau[k]), thin(tau[k + 1])}, V2{thin(tau[k + 1]), thin(tau[k + 2])});
    for (int lane = 0; lane < 2; ++lane) set(k + lane, {w.fp[lane], w.fq[lane], w.bq[lane], w.bp[lane], w.alpha[lane]});
  }
  if (k < count) set(k, thin_piece_weights(thin(tau[k]), thin(tau[k + 1])));
  for (int k : pieces.by_thickness) {
    if (pieces.thickest(k) * d <= piece_series::kThin) break;
    set(k, thick_piece_weights(tau[k] * d, tau[k + 1] * d));
  }
  for (int k = 0; k < count; ++k) {
    const TfSample& p = tf[k];
    const TfSample& q = tf[k + 1];
    const PieceWeights w{s.fp[k], s.fq[k], s.bq[k], s.bp[k], s.alpha[k]};
    // Built in registers, then stored: chained stores would be reloaded.
    const SlabRgba f{p.r * w.fp + q.r * w.fq, p.g * w.fp + q.g * w.fq, p.b * w.fp + q.b * w.fq, w.alpha};
    const SlabRgba b{q.r * w.bq + p.r * w.bp, q.g * w.bq + p.g * w.bp, q.b * w.bq + p.b * w.bp, w.alpha};
    s.head_f[k] = s.tail_f[k] = f;
    s.head_b[k] = s.tail_b[k] = b;
  }
  for (int start = 0; start < count; start += m) {
    const int end = std::min(start + m, count);
    // Four independent chains in one loop, so they overlap in the pipeline.
    for (int h = start + 1, t = end - 2; h < end; ++h, --t) {
      s.head_f[h] = over(s.head_f[h - 1], s.head_f[h]);
      s.head_b[h] = over(s.head_b[h], s.head_b[h - 1]);
      s.tail_f[t] = over(s.tail_f[t], s.tail_f[t + 1]);
      s.tail_b[t] = over(s.tail_b[t + 1], s.tail_b[t]);
    }
  }
  // Entry (i, i+m) covers pieces i .. e = i+m-1: a whole bin, or the tail of
  // one bin followed by the head of the next.
  for (int i = 0, in_bin = 0; i + m < n; ++i, in_bin = in_bin + 1 == m ? 0 : in_bin + 1) {
    const int e = i + m - 1;
    if (in_bin == 0) {  // i % m == 0, without a division per entry
      upper[i] = to_entry(s.tail_f[i]);
      lower[i] = to_entry(s.tail_b[i]);
    } else {
      upper[i] = to_entry(over(s.tail_f[i], s.head_f[e]));
      lower[i] = to_entry(over(s.head_b[e], s.tail_b[i]));
    }
  }
}

// Diagonals are built kGroup at a time and stored row by row: entries
// (i, i+m0 .. i+m0+kGroup-1) are adjacent in memory, one diagonal is not.
constexpr int kGroup = 32;

void build_group(const DiscreteTf& tf, const Pieces& pieces, double length, int m0, Scratch& s,
                 PreintegrationTable& table) {
  const int n = tf.size(), m1 = std::min(m0 + kGroup, n);
  const auto at = [n](int m_offset, int i) { return std::size_t(m_offset) * n + i; };
  for (int m = m0; m < m1; ++m) build_diagonal(tf, pieces, length, m, s, &s.upper[at(m - m0, 0)], &s.lower[at(m - m0, 0)]);
  for (int r = 0; r < n; ++r)
    for (int m = m0; m < m1; ++m) {
      if (r + m < n) std::copy_n(s.upper[at(m - m0, r)].data(), 4, table.entry(r, r + m));
      if (r - m >= 0) std::copy_n(s.lower[at(m - m0, r - m)].data(), 4, table.entry(r, r - m));
    }
}

}  // namespace

PreintegrationTable IncrementalBuilder::build(const DiscreteTf& tf, double length) const {
  check_slab_length(length);
  PreintegrationTable table(tf.axis(), length);
  const int n = tf.size();
  for (int i = 0; i < n; ++i) std::copy_n(to_entry(homogeneous_slab(tf[i], length)).data(), 4, table.entry(i, i));
  const Pieces pieces(tf);
  // Scratch is reused by whichever thread runs a group and fully overwritten
  // before it is read, so the bytes do not depend on the thread count.
  tbb::enumerable_thread_specific<Scratch> scratch([n] {
    Scratch s;
    for (auto* v : {&s.fp, &s.fq, &s.bq, &s.bp, &s.alpha}) v->resize(n - 1);
    for (auto* v : {&s.head_f, &s.tail_f, &s.head_b, &s.tail_b}) v->resize(n - 1);
    s.upper.resize(std::size_t(kGroup) * n);
    s.lower.resize(std::size_t(kGroup) * n);
    return s;
  });
  const int groups = (n - 1 + kGroup - 1) / kGroup;
  tbb::parallel_for(0, groups, [&](int g) { build_group(tf, pieces, length, 1 + g * kGroup, scratch.local(), table); });
  return table;
}

}  // namespace vri
