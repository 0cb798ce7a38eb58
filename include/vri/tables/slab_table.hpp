#pragma once
// SlabTable: a pre-integration table over (l, s_f, s_b) - the premultiplied
// (C, alpha) of a ray segment of length l on which the scalar goes linearly
// from s_f to s_b (Roettger & Ertl 2002, Sec. 3; the third dimension of the
// table of Roettger, Kraus & Ertl 2000). Mesh methods depend only on this
// interface, so any builder can stand behind it.
#include "vri/core/rgba.hpp"

namespace vri {

class SlabTable {
 public:
  virtual ~SlabTable() = default;
  // l in [0, max_length()]; scalars outside the table's range are clamped to it.
  virtual Rgba lookup(double l, double s_f, double s_b) const = 0;
  virtual double max_length() const = 0;
};

}  // namespace vri
