#pragma once
// The machinery of incremental subrange integration (Lum, Wilson & Ma 2004,
// §4.2, Figs. 4-5), shared by IncrementalBuilder and WeightedBuilder.
// Diagonal m of an N x N table holds the entries (i, i+m) and (i+m, i); each
// covers m pieces (table scalars k, k+1) of length l/m. The piece weights
// depend only on the extinction, so one DiagonalSweep::weights() serves any
// number of colour sets composited over it with composite().
#include <algorithm>
#include <array>
#include <numeric>
#include <vector>

#include "tables/discrete_tf.hpp"
#include "tables/piece_weights.hpp"
#include "tables/preintegration_table.hpp"
#include "tables/slab_rgba.hpp"

namespace vri {

// What every diagonal needs from the transfer function: per piece k (table
// scalars k, k+1) its end extinctions, and the pieces by decreasing
// extinction, so the pieces too thick for the series at piece length d are
// a prefix of `by_thickness`. A split bin (DiscreteTf::sub_pieces) is one
// piece too, a "super-segment": its (C, alpha) at piece length d, forward and
// backward, is its sub-pieces composited exactly (integrate_sub_pieces), so
// every entry that covers whole bins is exact, as brute's, in O(N^2 + N K)
// for K sub-pieces.
struct Pieces {
  const DiscreteTf* tf;
  std::vector<double> tau;        // tau[k] at table scalar k
  std::vector<int> by_thickness;  // piece indices, max(tau_k, tau_k+1) decreasing
  std::vector<double> split_depth;  // per split bin (tf->split_bins()), int tau du over its sub-pieces
  explicit Pieces(const DiscreteTf& tf) : tf(&tf), tau(tf.size()), by_thickness(tf.size() - 1) {
    for (int k : tf.split_bins()) {
      double depth = 0;
      for (const SubPiece& s : tf.sub_pieces(k)) depth += 0.5 * (s.p.tau + s.q.tau) * (s.u1 - s.u0);
      split_depth.push_back(depth);
    }
    for (int k = 0; k < tf.size(); ++k) tau[k] = tf[k].tau;
    std::iota(by_thickness.begin(), by_thickness.end(), 0);
    std::stable_sort(by_thickness.begin(), by_thickness.end(),
                     [&](int a, int b) { return thickest(a) > thickest(b); });
  }
  int size() const { return static_cast<int>(tau.size()); }
  double thickest(int k) const { return std::max(tau[k], tau[k + 1]); }
};

using Entry = std::array<float, 4>;

// Scratch of one thread, fully overwritten by each weights() / composite(),
// so results do not depend on which thread ran what. On x86-64 with VRI_SIMD
// the loops are compiled twice (AVX2 + FMA and the x86-64 baseline,
// target_clones, src/core/simd.hpp) and picked at run time: one machine
// always runs the same code, whatever the thread count.
class DiagonalSweep {
 public:
  explicit DiagonalSweep(int n);

  // The piece weights of diagonal m (pieces of length `length` / m); a split
  // bin's alpha from its sub-pieces.
  void weights(const Pieces& pieces, double length, int m);

  // Composites the colours c[0 .. n-1] (r, g, b of TfSample; tau is the
  // pieces') over diagonal m (after weights(..., m)): upper[i] = entry
  // (i, i+m), lower[i] = entry (i+m, i), i = 0 .. n-1-m; or straight into
  // the table's entries, rounded to float. `subs` are the split bins'
  // sub-pieces with their colours, laid out as DiscreteTf::all_sub_pieces().
  void composite(const TfSample* c, const SubPiece* subs, int m, SlabRgba* upper, SlabRgba* lower);
  void composite(const TfSample* c, const SubPiece* subs, int m, PreintegrationTable& table);

  // Per piece k (table scalars k, k+1): the weights of piece_weights.hpp,
  // planar so the series loop vectorises.
  struct Weights {
    std::vector<double> fp, fq, bq, bp, alpha;
  };
  // Per piece, each a whole premultiplied (C, alpha) (SlabRgba layout, one
  // AVX2 register): the piece itself, forward (front = lower scalar) and
  // backward (front = higher scalar), and its subranges within its bin
  // (pieces [b m, (b+1) m), Lum et al. 2004, Fig. 5):
  //   head[k] = pieces bin_start..k   (left-hand subrange grown to the right)
  //   tail[k] = pieces k..bin_end-1   (right-hand subrange grown to the left)
  struct Subranges {
    std::vector<SlabRgba> piece_f, piece_b, head_f, tail_f, head_b, tail_b;
  };
  // The split bins' super-segments, forward and backward, for composite().
  struct SplitBins {
    const int* bins = nullptr;
    int count = 0;
    std::vector<SlabRgba> f, b;
  };

 private:
  void split_pieces(const SubPiece* subs);
  Weights w_;
  Subranges s_;
  SplitBins split_;
  const Pieces* pieces_ = nullptr;
  double d_ = 0;  // piece length of the last weights()
};

inline Entry to_entry(double r, double g, double b, double a) {
  return {static_cast<float>(r), static_cast<float>(g), static_cast<float>(b), static_cast<float>(a)};
}
inline Entry to_entry(const SlabRgba& v) { return to_entry(v.r, v.g, v.b, v.a); }

}  // namespace vri
