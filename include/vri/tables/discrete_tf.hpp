#pragma once
// DiscreteTf: the transfer function as every pre-integration table sees it
// (SPEC §10). It is sampled at N table scalars
//   x_i = s_lo + i * (s_hi - s_lo) / (N - 1),   i = 0 .. N-1,
// [s_lo, s_hi] spanning the control points, and r, g, b, tau are taken as
// linear in s between neighbouring x_i. When every control point lies on some
// x_i this is the transfer function itself.
#include <vector>

#include "vri/transfer/transfer_function.hpp"

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

class DiscreteTf {
 public:
  // Throws vri::Error unless 2 <= n <= kMaxSize.
  DiscreteTf(const TransferFunction& tf, int n);
  static constexpr int kMaxSize = 4096;  // a 4096 x 4096 table is 256 MiB

  const ScalarAxis& axis() const { return axis_; }
  int size() const { return axis_.n; }
  // The transfer function at x_i.
  const TfSample& operator[](int i) const { return samples_[i]; }
  // Linear between the samples at a continuous index u in [0, n-1].
  TfSample at_index(double u) const;

 private:
  ScalarAxis axis_;
  std::vector<TfSample> samples_;
};

}  // namespace vri
