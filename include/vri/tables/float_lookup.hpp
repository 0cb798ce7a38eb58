#pragma once
// FloatLookup: PreintegrationTable::lookup for preint1's float path (issue 8;
// docs/PERFORMANCE.md): the continuous index is (s - s_lo) * scale with the
// scale precomputed (no division), clamped as ScalarAxis::index, and the four
// entries are blended as 4-float vectors (GCC vector extension; SSE2 on
// x86-64). An all-zero neighbourhood gives exactly zero, as the double lookup.
#include <algorithm>
#include <cstring>

#include "vri/core/rgba.hpp"
#include "vri/tables/preintegration_table.hpp"

namespace vri {

using Float4 = float __attribute__((vector_size(16)));

class FloatLookup {
 public:
  explicit FloatLookup(const PreintegrationTable& table)
      : data_(table.data().data()),
        n_(table.size()),
        row_(4 * static_cast<std::size_t>(n_)),
        lo_(static_cast<float>(table.axis().s_lo)),
        scale_(table.axis().s_hi > table.axis().s_lo
                   ? static_cast<float>((n_ - 1) / (table.axis().s_hi - table.axis().s_lo))
                   : 0.0f),
        top_(static_cast<float>(n_ - 1)) {}

  // A scalar's place on the table axis: entry i and the weight w of entry i + 1
  // (found once per sample: it serves the slabs on both sides).
  struct Place {
    int i;
    float w;
  };
  Place place(float s) const {
    const float u = std::clamp((s - lo_) * scale_, 0.0f, top_);
    const int i = std::min(static_cast<int>(u), n_ - 2);
    return {i, u - i};
  }
  // Where the lookup of a slab from front to back reads, and the weights of
  // what it reads; finding it starts loading the entries, so a march can find
  // the next slab's spot before it blends the current one.
  struct Spot {
    const float* entry;  // (f, b); the others are (f, b + 1), (f + 1, b), (f + 1, b + 1)
    float wf, wb;
  };
  Spot find(Place front, Place back) const {
    const float* e = data_ + 4 * (static_cast<std::size_t>(front.i) * n_ + back.i);
    __builtin_prefetch(e);
    __builtin_prefetch(e + row_);
    return {e, front.w, back.w};
  }
  // What `place` and `find` read, for the ray packets (src/integrators/float_packet.cpp).
  const float* data() const { return data_; }
  int size() const { return n_; }
  float lo() const { return lo_; }
  float scale() const { return scale_; }
  float top() const { return top_; }
  // Bilinear in the continuous indices of s_f and s_b: premultiplied (r, g, b, alpha).
  Float4 blend(const Spot& spot) const {
    const float* e = spot.entry;
    const Float4 e00 = load(e), e01 = load(e + 4), e10 = load(e + row_), e11 = load(e + row_ + 4);
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
  static Float4 load(const float* p) {
    Float4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  const float* data_;
  int n_;
  std::size_t row_;  // floats per table row
  float lo_, scale_, top_;
};

}  // namespace vri
