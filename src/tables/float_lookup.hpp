#pragma once
// FloatLookup: PreintegrationTable::lookup for preint1's float path (issue 8;
// docs/PERFORMANCE.md): the continuous index is (s - s_lo) * scale with the
// scale precomputed (no division), clamped as ScalarAxis::index, and the four
// entries are blended as 4-float vectors (GCC vector extension; SSE2 on
// x86-64, NEON on aarch64). An all-zero neighbourhood gives exactly zero, as the double lookup.
#include <algorithm>
#include <array>
#include <cstring>

#include "vri/geometry.hpp"
#include "tables/preintegration_table.hpp"

namespace vri {

using Float4 = float __attribute__((vector_size(16)));

// A scalar's place on a table axis in float: entry i and the weight w of
// entry i + 1, the continuous index (s - s_lo) * scale clamped as
// ScalarAxis::index, the scale precomputed (no division). Found once per
// sample, it serves the slabs on both sides of it.
class FloatAxis {
 public:
  explicit FloatAxis(const ScalarAxis& axis)
      : n_(axis.n),
        lo_(static_cast<float>(axis.s_lo)),
        scale_(axis.s_hi > axis.s_lo ? static_cast<float>((axis.n - 1) / (axis.s_hi - axis.s_lo)) : 0.0f),
        top_(static_cast<float>(axis.n - 1)) {}

  struct Place {
    int i;
    float w;
  };
  Place place(float s) const {
    const float u = std::clamp((s - lo_) * scale_, 0.0f, top_);
    const int i = std::min(static_cast<int>(u), n_ - 2);
    return {i, u - i};
  }
  // What `place` reads, for the ray packets (src/methods/preint/float_packet.cpp).
  int size() const { return n_; }
  float lo() const { return lo_; }
  float scale() const { return scale_; }
  float top() const { return top_; }

 private:
  int n_;
  float lo_, scale_, top_;
};

inline Float4 load_float4(const float* p) {
  Float4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

class FloatLookup {
 public:
  static constexpr int kSteps = 1;  // a slab is one step: front and back samples
  explicit FloatLookup(const PreintegrationTable& table)
      : axis_(table.axis()), data_(table.data().data()), row_(4 * static_cast<std::size_t>(axis_.size())) {}

  using Place = FloatAxis::Place;
  Place place(float s) const { return axis_.place(s); }
  // Where the lookup of a slab from front to back reads, and the weights of
  // what it reads; finding it starts loading the entries, so a march can find
  // the next slab's spot before it blends the current one.
  struct Spot {
    const float* entry;  // (f, b); the others are (f, b + 1), (f + 1, b), (f + 1, b + 1)
    float wf, wb;
  };
  Spot find(Place front, Place back) const {
    const float* e = data_ + 4 * (static_cast<std::size_t>(front.i) * axis_.size() + back.i);
    __builtin_prefetch(e);
    __builtin_prefetch(e + row_);
    return {e, front.w, back.w};
  }
  Spot find(const std::array<Place, 2>& p) const { return find(p[0], p[1]); }
  // What `place` and `find` read, for the ray packets (src/methods/preint/float_packet.cpp).
  const FloatAxis& axis() const { return axis_; }
  const float* data() const { return data_; }
  int size() const { return axis_.size(); }
  // Bilinear in the continuous indices of s_f and s_b: premultiplied (r, g, b, alpha).
  Float4 blend(const Spot& spot) const { return blend(spot, data_); }
  // The same spot in another table of this one's layout (the weighted
  // tables of interpolated lighting).
  Float4 blend(const Spot& spot, const float* table) const {
    const float* e = table + (spot.entry - data_);
    const Float4 e00 = load_float4(e), e01 = load_float4(e + 4), e10 = load_float4(e + row_),
                 e11 = load_float4(e + row_ + 4);
    const Float4 front = e00 + spot.wb * (e01 - e00), back = e10 + spot.wb * (e11 - e10);
    return front + spot.wf * (back - front);
  }
  // The same as a PreintegrationTable::lookup (the interface of the slab
  // policies, slab_policies.hpp), in float.
  Rgba lookup(double s_f, double s_b) const {
    const Float4 v = blend(find(place(static_cast<float>(s_f)), place(static_cast<float>(s_b))));
    return {v[0], v[1], v[2], v[3]};
  }

 private:
  FloatAxis axis_;
  const float* data_;
  std::size_t row_;  // floats per table row
};

}  // namespace vri
