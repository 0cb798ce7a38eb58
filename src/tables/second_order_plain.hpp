#pragma once
// PlainSecondOrderBuilder: the reference second-order builder. Every entry is
// iterated on its own exactly as second_order_table.hpp defines it (El Hajjar
// et al. 2008, Eq. 2, iterated as in their §6.2), in double precision,
// parallel over s_f (oneTBB).
// O(N^3 K); 256^3 at K = 64 takes minutes of CPU, like the paper's 165 s.
#include "tables/second_order_weighted.hpp"

namespace vri {

class PlainSecondOrderBuilder final : public SecondOrderBuilder {
 public:
  std::string_view name() const override { return "plain"; }
  SecondOrderTable build(const DiscreteTf& tf, double length, int iterations) const override;
  SecondOrderWeightedTables build_weighted(const DiscreteTf& tf, double length, int iterations) const override;
};

}  // namespace vri
