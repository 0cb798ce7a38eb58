#pragma once
// Pre-integration tables (Engel, Kraus & Ertl 2001): the slab integral of
// slab_integral.hpp tabulated at the table scalars, float32 premultiplied
// RGBA. PreintegrationTable is one slab length, indexed [s_f][s_b];
// LengthTable adds the length axis, indexed [l][s_f][s_b] with lengths
// max_length * m / (M - 1) (SPEC §10). Lookups interpolate linearly in every axis.
#include <cstddef>
#include <span>
#include <vector>

#include "vri/geometry.hpp"
#include "vri/memory.hpp"
#include "tables/discrete_tf.hpp"
#include "tables/slab_table.hpp"

namespace vri {

class PreintegrationTable {
 public:
  PreintegrationTable(const ScalarAxis& axis, double length);

  const ScalarAxis& axis() const { return axis_; }
  int size() const { return axis_.n; }
  double length() const { return length_; }
  // Entry (f, b): 4 floats r, g, b, alpha.
  float* entry(int f, int b) { return &data_[4 * (static_cast<std::size_t>(f) * axis_.n + b)]; }
  const float* entry(int f, int b) const { return &data_[4 * (static_cast<std::size_t>(f) * axis_.n + b)]; }
  std::span<const float> data() const { return {data_.data(), data_.size()}; }

  // Bilinear in the continuous indices of s_f and s_b.
  Rgba lookup(double s_f, double s_b) const;

 private:
  ScalarAxis axis_;
  double length_;
  // Zero until written; 2 MiB pages: the builders' own writes fault the
  // table in, without a memset first (zeroed_floats.hpp).
  ZeroedFloats data_;
};

// The table the mesh methods (tet-raycast, pt) sample, whatever builder made it.
class LengthTable final : public SlabTable {
 public:
  // slices[m] must have length max_length * m / (M - 1); M >= 2.
  LengthTable(std::vector<PreintegrationTable> slices, double max_length);

  const std::vector<PreintegrationTable>& slices() const { return slices_; }
  double max_length() const override { return max_length_; }
  const ScalarAxis& axis() const override { return slices_.front().axis(); }
  // The (M, N, N, 4) array, C order.
  std::vector<float> data() const;
  // Linear in l (clamped to [0, max_length]) between the two nearest slices.
  Rgba lookup(double length, double s_f, double s_b) const override;

 private:
  std::vector<PreintegrationTable> slices_;
  double max_length_;
};

}  // namespace vri
