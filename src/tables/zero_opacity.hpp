#pragma once
// ZeroOpacity: where a transfer function has zero extinction, as an
// integrator sees it, so that empty-space skipping (volume/empty_space.hpp)
// drops only what contributes nothing. `over(lo, hi)` is true only when every
// scalar in [lo, hi] contributes exactly zero:
// - from a TransferFunction (riemann): every linear piece that tf(s) evaluates
//   for s in [lo, hi] has tau = 0 and slope 0, so tf(s).tau is exactly 0;
// - from a DiscreteTf (pre-integrated methods): every table scalar x_i that a
//   bilinear lookup at s in [lo, hi] gives a weight, i from floor(index(lo))
//   to ceil(index(hi)), has tau = 0, and so has every bin between them (a
//   bin split at control points, DiscreteTf::sub_pieces, with extinction
//   inside counts as opaque at both its table scalars); a table entry (f, b)
//   integrates the transfer function between x_f and x_b, so it is zero;
// - from a DiscreteTf for second-order tables (preint2, TableOrder::Second):
//   an entry (f, m, b) integrates along the parabola through the table
//   scalars x_f, x_m, x_b (second_order_table.hpp), which leaves their range
//   by up to 1/8 of its width (the Lagrange basis on [0, 1] dips to -1/8 at
//   t = 1/4 and 3/4) before it is clamped to the axis. So the entries
//   i = floor(index(lo)) .. ceil(index(hi)) must lie in a run a..b of
//   zero-tau table scalars with zero-tau bins between them (a bin split by a
//   control point ends a run, but its table scalars stay in the runs on either
//   side when their own tau is 0: fuel's 64-entry table then skips its
//   background), at least (b - a)/8 (+ 1e-3 for rounding) away from
//   each end of the run that is not an end of the axis: then any three of
//   them span at most b - a, their parabola stays inside a..b, and every
//   sub-step of the entry reads tau = 0 and colour times alpha = 0. The
//   condition holds for the union of overlapping ranges that each meet it
//   (they lie in the same run), so a slab whose three samples lie in a run of
//   such macro cells reads zero entries (volume/empty_space.hpp).
// Each query is O(1) after a binary search, so reclassifying every macro cell
// after a transfer-function edit takes milliseconds (bench_macro_cells).
#include <algorithm>
#include <vector>

#include "tables/discrete_tf.hpp"
#include "vri/transfer_function.hpp"

namespace vri {

// The table a DiscreteTf feeds: first order (slabs with the scalar linear)
// or second order (slabs with the scalar a parabola).
enum class TableOrder { First, Second };

class ZeroOpacity {
 public:
  explicit ZeroOpacity(const TransferFunction& tf);
  explicit ZeroOpacity(const DiscreteTf& tf, TableOrder order = TableOrder::First);

  // True when no scalar in [lo, hi] (lo <= hi) contributes.
  bool over(double lo, double hi) const;

 private:
  const TransferFunction* tf_ = nullptr;  // riemann: pieces of tf_; else table scalars of axis_
  ScalarAxis axis_;
  TableOrder order_ = TableOrder::First;
  std::vector<int> opaque_before_;  // opaque_before_[i]: pieces (or table scalars) 0..i-1 with tau != 0
};

// ZeroOpacityBins: ZeroOpacity::over in O(1) without a search, for ranges
// inside a known span [lo, hi] (a volume's range, with a margin), as a hot
// loop needs it (the guaranteed adaptive integrator asks once per cell). The
// span is cut into `bins` equal bins, each marked when ZeroOpacity::over
// fails on it (widened by a rounding margin); over(a, b) is true only when
// [a, b] lies in the span and no bin it touches is marked. Conservative: it
// may say false where ZeroOpacity says true (a bin that a control point
// cuts), never the reverse.
class ZeroOpacityBins {
 public:
  ZeroOpacityBins(const ZeroOpacity& zero, double lo, double hi, int bins = 4096);
  bool over(double a, double b) const {
    if (!(a >= lo_ && b <= hi_)) return false;
    return marked_before_[bin(b) + 1] == marked_before_[bin(a)];
  }

 private:
  int bin(double s) const { return std::min(static_cast<int>((s - lo_) * scale_), last_); }
  double lo_, hi_, scale_;
  int last_;
  std::vector<int> marked_before_;  // marked_before_[i]: marked bins among 0 .. i - 1
};

}  // namespace vri
