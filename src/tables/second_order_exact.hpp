#pragma once
// ExactSecondOrderBuilder: every entry the slab integral along the continuous
// parabola of El Hajjar et al. 2008 (Eq. 2), to 1e-7 - the reference the
// other second-order builders are measured against (issue 16). An entry is
// second_order_entry() with K = 64 chords, then K doubled until two
// successive values differ by at most 1e-7 in every channel (the chords
// converge as O(1/K^2), so the last change bounds the remaining error to
// about a third of it), at most K = kMaxSecondOrderIterations. `iterations`
// is ignored. O(N^3 K): tables up to kMaxSize a side (vri::Error beyond).
#include "tables/second_order_weighted.hpp"

namespace vri {

class ExactSecondOrderBuilder final : public SecondOrderBuilder {
 public:
  static constexpr double kTolerance = 1e-7;
  static constexpr int kMaxSize = 64;
  std::string_view name() const override { return "exact"; }
  SecondOrderTable build(const DiscreteTf& tf, double length, int iterations) const override;
  SecondOrderWeightedTables build_weighted(const DiscreteTf& tf, double length, int iterations) const override;
};

// One entry of the builder above, at continuous indices.
SecondOrderWeights exact_second_order_entry(const DiscreteTf& tf, double u_f, double u_m, double u_b, double length);

}  // namespace vri
