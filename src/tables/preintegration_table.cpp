#include "tables/preintegration_table.hpp"

#include <algorithm>

#include "vri/error.hpp"

namespace vri {

namespace {

// The lower of the two entries around continuous index u, and the weight of the upper.
struct Bracket {
  int i;
  double w;
};
Bracket bracket(double u, int n) {
  const int i = std::min(static_cast<int>(u), n - 2);
  return {i, u - i};
}

}  // namespace

PreintegrationTable::PreintegrationTable(const ScalarAxis& axis, double length)
    : axis_(axis), length_(length), data_(4 * static_cast<std::size_t>(axis.n) * axis.n) {}

Rgba PreintegrationTable::lookup(double s_f, double s_b) const {
  const Bracket f = bracket(axis_.index(s_f), axis_.n), b = bracket(axis_.index(s_b), axis_.n);
  const float* e00 = entry(f.i, b.i);
  const float* e01 = entry(f.i, b.i + 1);
  const float* e10 = entry(f.i + 1, b.i);
  const float* e11 = entry(f.i + 1, b.i + 1);
  Rgba out;
  for (int c = 0; c < 4; ++c)
    out[c] = (1 - f.w) * ((1 - b.w) * e00[c] + b.w * e01[c]) + f.w * ((1 - b.w) * e10[c] + b.w * e11[c]);
  return out;
}

LengthTable::LengthTable(std::vector<PreintegrationTable> slices, double max_length)
    : slices_(std::move(slices)), max_length_(max_length) {
  if (slices_.size() < 2) throw Error("a table with lengths needs at least 2 lengths");
}

std::vector<float> LengthTable::data() const {
  std::vector<float> out;
  out.reserve(slices_.size() * slices_.front().data().size());
  for (const auto& s : slices_) out.insert(out.end(), s.data().begin(), s.data().end());
  return out;
}

Rgba LengthTable::lookup(double length, double s_f, double s_b) const {
  const LengthBracket l = length_bracket(length, max_length_, static_cast<int>(slices_.size()));
  const Rgba lo = slices_[l.i].lookup(s_f, s_b), hi = slices_[l.i + 1].lookup(s_f, s_b);
  Rgba out;
  for (int c = 0; c < 4; ++c) out[c] = (1 - l.w) * lo[c] + l.w * hi[c];
  return out;
}

}  // namespace vri
