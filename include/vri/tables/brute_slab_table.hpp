#pragma once
// BruteSlabTable: the (l, s_f, s_b) table filled entry by entry with the exact
// piece integral (PieceIntegrator), then sampled trilinearly. Simple and
// accurate but O(M N^2) exact integrals to build; it stands in until the fast
// builders of the pre-integration-table work replace it behind SlabTable.
// Layout as `vri table --lengths` (SPEC §10): entry [m][i][j] is the segment
// of length max_length * m / (M-1) from s_i to s_j, s_i = s_lo + i (s_hi - s_lo) / (N-1),
// [s_lo, s_hi] spanning the transfer function's control points.
#include <vector>

#include "vri/tables/slab_table.hpp"
#include "vri/transfer/transfer_function.hpp"

namespace vri {

class BruteSlabTable final : public SlabTable {
 public:
  // size N >= 2 scalars a side, lengths M >= 2, max_length > 0; each entry
  // exact to 1e-7. Builds on all cores; the result does not depend on how many.
  BruteSlabTable(const TransferFunction& tf, int size, int lengths, double max_length);

  Rgba lookup(double l, double s_f, double s_b) const override;
  double max_length() const override { return max_length_; }
  int size() const { return n_; }
  int lengths() const { return m_; }
  const std::vector<float>& data() const { return data_; }  // [m][i][j][rgba]

 private:
  int n_, m_;
  double max_length_, s_lo_, s_scale_;
  std::vector<float> data_;
};

}  // namespace vri
