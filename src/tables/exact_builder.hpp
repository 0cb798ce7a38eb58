#pragma once
// ExactBuilder (`--builder exact`): every entry is the exact slab integral of
// slab_integral.hpp on its own, exact_slab through every table scalar and
// every control point between s_f and s_b, each linear piece by
// linear_piece (closed-form weights, series or Gauss-Legendre to 1e-12
// relative). The reference every other builder is tested against
// (tests/tables/exact_builder_test.cpp), itself checked against closed
// forms and an independent quadrature of the TransferFunction. O(N^2 (N + K)).
#include "tables/table_builder.hpp"

namespace vri {

class ExactBuilder final : public TableBuilder {
 public:
  std::string_view name() const override { return "exact"; }
  // n^2 entries of (n + 2) / 3 bins on average, each in closed form (two exponentials).
  double work(int n) const override { return 2.0 * n * n * (n + 2) / 3; }
  PreintegrationTable build(const DiscreteTf& tf, double length) const override;
};

}  // namespace vri
