#pragma once
// FloatLookup: PreintegrationTable::lookup for preint1's float path (issue 8;
// docs/PERFORMANCE.md): the continuous index is (s - s_lo) * scale with the
// scale precomputed (no division), clamped as ScalarAxis::index, and the four
// entries are blended as 4-float vectors (GCC vector extension; SSE2 on
// x86-64). An all-zero neighbourhood gives exactly zero, as the double lookup.
#include <algorithm>
#include <cstring>

#include "vri/tables/preintegration_table.hpp"

namespace vri {

using Float4 = float __attribute__((vector_size(16)));

class FloatLookup {
 public:
  explicit FloatLookup(const PreintegrationTable& table)
      : data_(table.data().data()),
        n_(table.size()),
        lo_(static_cast<float>(table.axis().s_lo)),
        scale_(table.axis().s_hi > table.axis().s_lo
                   ? static_cast<float>((n_ - 1) / (table.axis().s_hi - table.axis().s_lo))
                   : 0.0f),
        top_(static_cast<float>(n_ - 1)) {}

  // Bilinear in the continuous indices of s_f and s_b: premultiplied (r, g, b, alpha).
  Float4 operator()(float s_f, float s_b) const {
    const float uf = index(s_f), ub = index(s_b);
    const int f = cell(uf), b = cell(ub);
    const float wf = uf - f, wb = ub - b;
    const float* e = entry(f, b);
    const std::size_t row = 4 * static_cast<std::size_t>(n_);
    const Float4 e00 = load(e), e01 = load(e + 4), e10 = load(e + row), e11 = load(e + row + 4);
    const Float4 front = e00 + wb * (e01 - e00), back = e10 + wb * (e11 - e10);
    return front + wf * (back - front);
  }

  // Starts loading the entries a later lookup at (s_f, s_b) reads.
  void prefetch(float s_f, float s_b) const {
    const float* e = entry(cell(index(s_f)), cell(index(s_b)));
    __builtin_prefetch(e);
    __builtin_prefetch(e + 4 * static_cast<std::size_t>(n_));
  }

 private:
  float index(float s) const { return std::clamp((s - lo_) * scale_, 0.0f, top_); }
  int cell(float u) const { return std::min(static_cast<int>(u), n_ - 2); }
  const float* entry(int f, int b) const { return data_ + 4 * (static_cast<std::size_t>(f) * n_ + b); }
  static Float4 load(const float* p) {
    Float4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  const float* data_;
  int n_;
  float lo_, scale_, top_;
};

}  // namespace vri
