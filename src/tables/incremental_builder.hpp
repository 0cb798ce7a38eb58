#pragma once
// IncrementalBuilder: incremental subrange integration (Lum, Wilson & Ma 2004,
// §4.2, Figs. 4-5). Entry (i, i+m) composites the m pieces between table
// scalars i and i+m, each of length l/m; the piece length depends only on
// the diagonal m, so along one diagonal the pieces are cut into bins of m:
// in each bin the left-hand subranges are grown to the right and the
// right-hand subranges to the left, and every entry joins one right-hand
// subrange of a bin with one left-hand subrange of the next (one "over").
// Below the diagonal the same with the pieces integrated and composited in
// the opposite direction. O(N^2) for N x N, exact to float rounding.
#include "tables/table_builder.hpp"

namespace vri {

class IncrementalBuilder final : public TableBuilder {
 public:
  std::string_view name() const override { return "incremental"; }
  // O(n^2): each entry from its neighbours (Lum, Wilson & Ma 2004).
  double work(int n) const override { return 4.0 * n * n; }
  PreintegrationTable build(const DiscreteTf& tf, double length) const override;
};

}  // namespace vri
