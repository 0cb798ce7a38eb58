#pragma once
// DiscreteTf: the transfer function as every pre-integration table sees it
// (SPEC §10). Its table axis has N table scalars
//   x_i = s_lo + i * (s_hi - s_lo) / (N - 1),   i = 0 .. N-1,
// [s_lo, s_hi] spanning the control points (SPEC §10, `vri table`) and, for
// rendering, the data's scalars too (table_axis). Between two neighbouring table
// scalars (a "bin") r, g, b, tau are the transfer function itself: linear when
// no control point falls inside the bin, else split into linear sub-pieces at
// the control points inside it (steps included). So a feature narrower than
// a bin is integrated, not dropped between samples (issue 16).
#include <optional>
#include <span>
#include <vector>

#include "vri/transfer_function.hpp"

namespace vri {

// The scalar axis of a table: entry i stands for x_i above.
struct ScalarAxis {
  double s_lo = 0, s_hi = 0;
  int n = 2;
  double scalar(int i) const { return s_lo + i * ((s_hi - s_lo) / (n - 1)); }
  // The continuous entry index of s, clamped to [0, n-1] (the end values hold
  // outside, as in SPEC §3). A one-scalar span maps everything to 0.
  double index(double s) const;
};

// The scalars a volume holds, [lo, hi]: what a rendering table must cover.
struct DataRange {
  double lo, hi;
};

// The axis of an n-entry table of `tf`: the control points' span (SPEC §10)
// widened to `data`. A slab whose scalar runs outside the axis was clamped
// into it, which moved the time it spends below the first point onto the
// first entry: below a step at the first point ("transparent below 50": two
// points at s = 50, the first point holding below, SPEC §3) every scalar took
// the value above, RMS 0.52 against `exact` (issue 46); below a ramp the
// slab saw more of the ramp than it crosses. Covering the data, no scalar a
// ray meets (trilinear or linear: within the data's range) is clamped.
ScalarAxis table_axis(const TransferFunction& tf, int n, std::optional<DataRange> data = std::nullopt);

// One linear piece of a bin, in continuous index units: p at u0, q at u1 (u0 <= u1).
struct SubPiece {
  double u0, u1;
  TfSample p, q;
};

class DiscreteTf {
 public:
  // Throws vri::Error unless 2 <= n <= kMaxSize. The axis: table_axis(tf, n,
  // data); rendering passes the volume's range, `vri table` none.
  DiscreteTf(const TransferFunction& tf, int n, std::optional<DataRange> data = std::nullopt);
  static constexpr int kMaxSize = 4096;  // a 4096 x 4096 table is 256 MiB

  const ScalarAxis& axis() const { return axis_; }
  int size() const { return axis_.n; }
  // The transfer function at x_i.
  const TfSample& operator[](int i) const { return samples_[i]; }
  // The transfer function at a continuous index u in [0, n-1]: linear between
  // the samples in a plain bin, the sub-pieces in a split one.
  TfSample at_index(double u) const;

  // Bin k (table scalars k, k+1) split at control points inside it: its
  // sub-pieces from u = k to u = k+1, in order; empty for a plain bin, which is
  // linear from (*this)[k] to (*this)[k+1].
  std::span<const SubPiece> sub_pieces(int k) const {
    return {subs_.data() + sub_begin_[k], subs_.data() + sub_begin_[k + 1]};
  }
  // The straight run of bin k: table scalars linear_begin(k) <= k and
  // linear_end(k) >= k + 1 between which every bin is plain and on one
  // segment of the transfer function (no control point inside or at the
  // scalars between), so r, g, b, tau are one line from end to end; k and
  // k + 1 for a split bin. A slab crosses such a run as one piece.
  int linear_begin(int k) const { return linear_begin_[k]; }
  int linear_end(int k) const { return linear_end_[k]; }
  // The split bins, ascending.
  const std::vector<int>& split_bins() const { return split_; }
  // All sub-pieces of the split bins, bin after bin (sub_begin(k) is bin k's first).
  const std::vector<SubPiece>& all_sub_pieces() const { return subs_; }
  int sub_begin(int k) const { return sub_begin_[k]; }

 private:
  ScalarAxis axis_;
  std::vector<TfSample> samples_;
  std::vector<int> sub_begin_;  // n + 1 entries: bin k's sub-pieces are [sub_begin_[k], sub_begin_[k+1])
  std::vector<SubPiece> subs_;
  std::vector<int> split_;
  std::vector<int> linear_begin_, linear_end_;  // n - 1 entries, one a bin
};

}  // namespace vri
