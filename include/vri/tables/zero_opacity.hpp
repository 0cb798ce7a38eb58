#pragma once
// ZeroOpacity: where a transfer function has zero extinction, as an
// integrator sees it, so that empty-space skipping (volume/empty_space.hpp)
// drops only what contributes nothing. `over(lo, hi)` is true only when every
// scalar in [lo, hi] contributes exactly zero:
// - from a TransferFunction (riemann): every linear piece that tf(s) evaluates
//   for s in [lo, hi] has tau = 0 and slope 0, so tf(s).tau is exactly 0;
// - from a DiscreteTf (pre-integrated methods): every table scalar x_i that a
//   bilinear lookup at s in [lo, hi] gives a weight, i from floor(index(lo))
//   to ceil(index(hi)), has tau = 0; a table entry (f, b) integrates the
//   discretised function between x_f and x_b, so it is zero.
// Each query is O(1) after a binary search, so reclassifying every macro cell
// after a transfer-function edit takes milliseconds (bench_macro_cells).
#include <vector>

#include "vri/tables/discrete_tf.hpp"
#include "vri/transfer/transfer_function.hpp"

namespace vri {

class ZeroOpacity {
 public:
  explicit ZeroOpacity(const TransferFunction& tf);
  explicit ZeroOpacity(const DiscreteTf& tf);

  // True when no scalar in [lo, hi] (lo <= hi) contributes.
  bool over(double lo, double hi) const;

 private:
  const TransferFunction* tf_ = nullptr;  // riemann: pieces of tf_; else table scalars of axis_
  ScalarAxis axis_;
  std::vector<int> opaque_before_;  // opaque_before_[i]: pieces (or table scalars) 0..i-1 with tau != 0
};

}  // namespace vri
