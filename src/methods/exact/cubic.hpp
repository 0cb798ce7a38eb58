#pragma once
// The trilinear field along a ray inside one cell, as a cubic in t, and the
// few operations exact integration needs on it.
#include <array>
#include <cmath>
#include <utility>

#include "vri/geometry.hpp"
#include "volume/cell_traversal.hpp"
#include "volume/gradient_field.hpp"
#include "vri/volume.hpp"

namespace vri {

// c[0] + c[1] t + c[2] t^2 + c[3] t^3
struct Cubic {
  std::array<double, 4> c{};
  double operator()(double t) const { return ((c[3] * t + c[2]) * t + c[1]) * t + c[0]; }
  double derivative(double t) const { return (3 * c[3] * t + 2 * c[2]) * t + c[1]; }
  // The line from v0 at t = 0 to v1 at t = len (constant v0 when len is 0).
  static Cubic linear(double v0, double v1, double len) { return {{v0, len > 0 ? (v1 - v0) / len : 0, 0, 0}}; }

  // Critical points strictly inside (0, len), ascending; returns how many (0..2).
  int critical_points(double len, double out[2]) const;

  // The t in [lo, hi] where this cubic, monotone there, equals `value`; the
  // caller guarantees value lies strictly between the end values.
  double solve_monotone(double value, double lo, double hi) const;
};

// A trilinear function along a cell segment, for t in [0, seg.tb - seg.ta]
// measured from seg.ta: substitute the local coordinates x(t) = x0 + p t (and
// y, z) into the form a + b x + c y + d z + e xy + f xz + g yz + h xyz of the
// cell's 8 corner values, given in the order c000, c100, c010, c110, c001,
// c101, c011, c111 (bit 0 = x, bit 1 = y, bit 2 = z).
Cubic trilinear_along(const std::array<double, 8>& corners, const CellSegment& seg);
// The scalar field along the segment.
Cubic trilinear_along(const GridVolume& vol, const CellSegment& seg);

// a * p + b * q
Cubic combine(double a, const Cubic& p, double b, const Cubic& q);

// The same cubic about x: shifted(c, x)(u) = c(x + u).
inline Cubic shifted(const Cubic& c, double x) {
  return {{c(x), c.derivative(x), c.c[2] + 3 * c.c[3] * x, c.c[3]}};
}

// The roots of the cubic strictly inside (0, len) where it changes sign,
// ascending; returns how many (0..3).
int sign_changes(const Cubic& s, double len, double out[3]);

// Lighting along a cell segment: the gradient as three cubics (grad) and the
// roots of N.dir inside (0, len), where |N.dir| has a kink (kinks, ascending);
// returns how many kinks (0..3).
int gradient_along(const GradientField& gradients, const CellSegment& seg, Vec3 dir, Cubic (&grad)[3],
                   double (&kinks)[3]);

}  // namespace vri
