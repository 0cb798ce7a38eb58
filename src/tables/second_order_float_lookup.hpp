#pragma once
// SecondOrderFloatLookup: SecondOrderTable::lookup for preint2's float path
// (issue 8; docs/PERFORMANCE.md, "Float paths and packets"), the second-order
// counterpart of FloatLookup: each sample is placed on the table axis once
// (FloatAxis), and a slab's eight entries (s_f, s_m, s_b and their upper
// neighbours) are blended as 4-float vectors, trilinear in the continuous
// indices: along s_b, then s_m, then s_f. An all-zero neighbourhood gives
// exactly zero, as the double lookup.
#include <array>
#include <cstddef>

#include "vri/geometry.hpp"
#include "tables/float_lookup.hpp"
#include "tables/second_order_table.hpp"

namespace vri {

class SecondOrderFloatLookup {
 public:
  static constexpr int kSteps = 2;  // a slab is two steps: front, middle and back samples
  explicit SecondOrderFloatLookup(const SecondOrderTable& table)
      : axis_(table.axis()),
        data_(table.data()),
        row_(4 * static_cast<std::size_t>(axis_.size())),
        plane_(row_ * static_cast<std::size_t>(axis_.size())) {}

  using Place = FloatAxis::Place;
  Place place(float s) const { return axis_.place(s); }

  // Where the lookup of a slab reads, and its weights; finding it starts
  // loading the entries (four lines of two entries each).
  struct Spot {
    const float* entry;  // (f, m, b); the others add 4 (b + 1), row (m + 1), plane (f + 1)
    float wf, wm, wb;
  };
  Spot find(const std::array<Place, 3>& p) const {
    const std::size_t at = offset(p[0].i, p[1].i, p[2].i);
    prefetch(at);
    return {data_ + at, p[0].w, p[1].w, p[2].w};
  }
  // Starts loading the four rows (two entries each) that a blend at entry
  // `at` (floats from the table's start) reads.
  void prefetch(std::size_t at) const {
    const float* e = data_ + at;
    __builtin_prefetch(e);
    __builtin_prefetch(e + row_);
    __builtin_prefetch(e + plane_);
    __builtin_prefetch(e + plane_ + row_);
  }
  Float4 blend(const Spot& spot) const { return blend(spot, data_); }
  // The same spot in another table of this one's layout (the weighted
  // tables of interpolated lighting).
  Float4 blend(const Spot& spot, const float* table) const {
    const float* e = table + (spot.entry - data_);
    const auto along_b = [&](const float* at) {
      const Float4 lo = load_float4(at), hi = load_float4(at + 4);
      return lo + spot.wb * (hi - lo);
    };
    const Float4 c00 = along_b(e), c01 = along_b(e + row_), c10 = along_b(e + plane_),
                 c11 = along_b(e + plane_ + row_);
    const Float4 c0 = c00 + spot.wm * (c01 - c00), c1 = c10 + spot.wm * (c11 - c10);
    return c0 + spot.wf * (c1 - c0);
  }

  // What `place` and `find` read, for the ray packets (src/methods/preint/float_packet.cpp).
  const FloatAxis& axis() const { return axis_; }
  const float* data() const { return data_; }
  int size() const { return axis_.size(); }
  // Floats from entry (f, m, b) to (f, m + 1, b) and to (f + 1, m, b).
  std::size_t row() const { return row_; }
  std::size_t plane() const { return plane_; }
  std::size_t offset(int f, int m, int b) const {
    return plane_ * static_cast<std::size_t>(f) + row_ * static_cast<std::size_t>(m) + 4 * static_cast<std::size_t>(b);
  }

 private:
  FloatAxis axis_;
  const float* data_;
  std::size_t row_, plane_;  // floats per (s_f, s_m) row and per s_f plane
};

}  // namespace vri
