#pragma once
// SlabTable: a pre-integration table over (l, s_f, s_b) - the premultiplied
// (C, alpha) of a ray segment of length l on which the scalar goes linearly
// from s_f to s_b (Roettger & Ertl 2002, Sec. 3; the third dimension of the
// table of Roettger, Kraus & Ertl 2000). Mesh methods depend only on this
// interface, so any builder can stand behind it.
#include <algorithm>

#include "vri/geometry.hpp"
#include "tables/discrete_tf.hpp"

namespace vri {

// Where a length falls among the M slices of a table with lengths
// max_length * m / (M - 1) (SPEC §10): slices i and i + 1 with the weight w of
// the upper one, l clamped to [0, max_length]. Shared by every table with a
// length axis (first and second order, double and float lookups).
struct LengthBracket {
  int i;
  double w;
};
inline LengthBracket length_bracket(double length, double max_length, int slices) {
  const double u = std::clamp(length / max_length, 0.0, 1.0) * (slices - 1);
  const int i = std::min(static_cast<int>(u), slices - 2);
  return {i, u - i};
}

class SlabTable {
 public:
  virtual ~SlabTable() = default;
  // l in [0, max_length()]; scalars outside the table's range are clamped to it.
  virtual Rgba lookup(double l, double s_f, double s_b) const = 0;
  virtual double max_length() const = 0;
  // The scalars its entries stand for (discrete_tf.hpp).
  virtual const ScalarAxis& axis() const = 0;
};

}  // namespace vri
