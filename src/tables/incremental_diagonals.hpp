#pragma once
// The machinery of incremental subrange integration (Lum, Wilson & Ma 2004,
// §4.2, Figs. 4-5), shared by IncrementalBuilder and WeightedBuilder.
// Diagonal m of an N x N table holds the entries (i, i+m) and (i+m, i); each
// covers m pieces (table scalars k, k+1) of length l/m. The piece weights
// depend only on the extinction, so one DiagonalSweep::weights() serves any
// number of colour sets composited over it with composite().
#include <algorithm>
#include <numeric>
#include <vector>

#include "vri/tables/discrete_tf.hpp"
#include "vri/tables/piece_weights.hpp"
#include "vri/tables/slab_rgba.hpp"

namespace vri {

// What every diagonal needs from the transfer function: per piece k (table
// scalars k, k+1) its end extinctions, and the pieces by decreasing
// extinction, so the pieces too thick for the series at piece length d are
// a prefix of `by_thickness`.
struct Pieces {
  std::vector<double> tau;        // tau[k] at table scalar k
  std::vector<int> by_thickness;  // piece indices, max(tau_k, tau_k+1) decreasing
  explicit Pieces(const DiscreteTf& tf) : tau(tf.size()), by_thickness(tf.size() - 1) {
    for (int k = 0; k < tf.size(); ++k) tau[k] = tf[k].tau;
    std::iota(by_thickness.begin(), by_thickness.end(), 0);
    std::stable_sort(by_thickness.begin(), by_thickness.end(),
                     [&](int a, int b) { return thickest(a) > thickest(b); });
  }
  int size() const { return static_cast<int>(tau.size()); }
  double thickest(int k) const { return std::max(tau[k], tau[k + 1]); }
};

// Scratch of one thread, fully overwritten by each weights() / composite(),
// so results do not depend on which thread ran what.
class DiagonalSweep {
 public:
  explicit DiagonalSweep(int n);

  // The piece weights of diagonal m (pieces of length `length` / m).
  void weights(const Pieces& pieces, double length, int m);

  // Composites the colours c[0 .. n-1] (r, g, b of TfSample; tau is the
  // pieces') over diagonal m (after weights(..., m)) and calls
  // store(i, upper, lower) with upper = entry (i, i+m), lower = entry (i+m, i).
  template <class Store>
  void composite(const TfSample* c, int m, Store&& store);

 private:
  // Piece weights as separate arrays, so the series loop vectorises.
  std::vector<double> fp_, fq_, bq_, bp_, alpha_;
  // Bins are pieces [b m, (b+1) m) (Lum et al. 2004, Fig. 5). Within each
  // bin, for piece k:
  //   head[k] = pieces bin_start..k   (left-hand subrange grown to the right)
  //   tail[k] = pieces k..bin_end-1   (right-hand subrange grown to the left)
  // forward (front = lower scalar) and backward (front = higher scalar).
  std::vector<SlabRgba> head_f_, tail_f_, head_b_, tail_b_;
};

template <class Store>
void DiagonalSweep::composite(const TfSample* c, int m, Store&& store) {
  const int count = static_cast<int>(fp_.size()), n = count + 1;
  for (int k = 0; k < count; ++k) {
    const TfSample& p = c[k];
    const TfSample& q = c[k + 1];
    const double fp = fp_[k], fq = fq_[k], bq = bq_[k], bp = bp_[k], alpha = alpha_[k];
    // Built in registers, then stored: chained stores would be reloaded.
    const SlabRgba f{p.r * fp + q.r * fq, p.g * fp + q.g * fq, p.b * fp + q.b * fq, alpha};
    const SlabRgba b{q.r * bq + p.r * bp, q.g * bq + p.g * bp, q.b * bq + p.b * bp, alpha};
    head_f_[k] = tail_f_[k] = f;
    head_b_[k] = tail_b_[k] = b;
  }
  for (int start = 0; start < count; start += m) {
    const int end = std::min(start + m, count);
    // Four independent chains in one loop, so they overlap in the pipeline.
    for (int h = start + 1, t = end - 2; h < end; ++h, --t) {
      head_f_[h] = over(head_f_[h - 1], head_f_[h]);
      head_b_[h] = over(head_b_[h], head_b_[h - 1]);
      tail_f_[t] = over(tail_f_[t], tail_f_[t + 1]);
      tail_b_[t] = over(tail_b_[t + 1], tail_b_[t]);
    }
  }
  // Entry (i, i+m) covers pieces i .. e = i+m-1: a whole bin, or the tail of
  // one bin followed by the head of the next.
  for (int i = 0, in_bin = 0; i + m < n; ++i, in_bin = in_bin + 1 == m ? 0 : in_bin + 1) {
    const int e = i + m - 1;
    if (in_bin == 0)  // i % m == 0, without a division per entry
      store(i, tail_f_[i], tail_b_[i]);
    else
      store(i, over(tail_f_[i], head_f_[e]), over(head_b_[e], tail_b_[i]));
  }
}

}  // namespace vri
