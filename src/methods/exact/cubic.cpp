#include "cubic.hpp"

#include <algorithm>

namespace vri {

int Cubic::critical_points(double len, double out[2]) const {
  // s'(t) = 3 c3 t^2 + 2 c2 t + c1 = 0, solved in the cancellation-free form.
  const double a = 3 * c[3], b = 2 * c[2], cc = c[1];
  double r[2];
  int n = 0;
  if (a == 0) {
    if (b != 0) r[n++] = -cc / b;
  } else {
    const double disc = b * b - 4 * a * cc;
    if (disc >= 0) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      if (q != 0) {
        r[n++] = q / a;
        r[n++] = cc / q;
      } else {
        r[n++] = 0;  // b = 0 and cc = 0: double root at 0
      }
    }
  }
  int m = 0;
  for (int i = 0; i < n; ++i)
    if (r[i] > 0 && r[i] < len) out[m++] = r[i];
  if (m == 2 && out[0] > out[1]) std::swap(out[0], out[1]);
  if (m == 2 && out[0] == out[1]) m = 1;
  return m;
}

double Cubic::solve_monotone(double value, double lo, double hi) const {
  // Newton's method kept inside a shrinking bracket (bisection when it strays).
  double flo = (*this)(lo) - value;
  const bool increasing = flo < 0;
  double x = 0.5 * (lo + hi);
  for (int it = 0; it < 100; ++it) {
    const double fx = (*this)(x) - value;
    if (fx == 0) return x;
    if ((fx < 0) == increasing) lo = x; else hi = x;
    const double d = derivative(x);
    double xn = d != 0 ? x - fx / d : 0.5 * (lo + hi);
    if (!(xn > lo && xn < hi)) xn = 0.5 * (lo + hi);
    if (std::abs(xn - x) <= 1e-15 * std::max(1.0, std::abs(x)) || hi - lo <= 1e-15 * std::max(1.0, std::abs(hi)))
      return xn;
    x = xn;
  }
  return x;
}

Cubic trilinear_along(const GridVolume& vol, const CellSegment& seg) {
  const int i = seg.cell[0], j = seg.cell[1], k = seg.cell[2];
  return trilinear_along({vol.at(i, j, k), vol.at(i + 1, j, k), vol.at(i, j + 1, k), vol.at(i + 1, j + 1, k),
                          vol.at(i, j, k + 1), vol.at(i + 1, j, k + 1), vol.at(i, j + 1, k + 1),
                          vol.at(i + 1, j + 1, k + 1)},
                         seg);
}

Cubic combine(double a, const Cubic& p, double b, const Cubic& q) {
  Cubic r;
  for (int k = 0; k < 4; ++k) r.c[k] = a * p.c[k] + b * q.c[k];
  return r;
}

int sign_changes(const Cubic& s, double len, double out[3]) {
  double knots[4];
  int nk = 0;
  knots[nk++] = 0;
  nk += s.critical_points(len, knots + 1);
  knots[nk++] = len;
  int n = 0;
  for (int m = 0; m + 1 < nk; ++m) {
    const double fa = s(knots[m]), fb = s(knots[m + 1]);
    if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) out[n++] = s.solve_monotone(0.0, knots[m], knots[m + 1]);
  }
  return n;
}

Cubic trilinear_along(const std::array<double, 8>& v, const CellSegment& seg) {
  const double c000 = v[0], c100 = v[1], c010 = v[2], c110 = v[3], c001 = v[4], c101 = v[5], c011 = v[6],
               c111 = v[7];
  // Monomial coefficients of the trilinear interpolant.
  const double a = c000, bx = c100 - c000, by = c010 - c000, bz = c001 - c000;
  const double exy = c110 - c100 - c010 + c000;
  const double exz = c101 - c100 - c001 + c000;
  const double eyz = c011 - c010 - c001 + c000;
  const double hxyz = c111 - c110 - c101 - c011 + c100 + c010 + c001 - c000;
  const double x0 = seg.local0.x, y0 = seg.local0.y, z0 = seg.local0.z;
  const double p = seg.local_dir.x, q = seg.local_dir.y, r = seg.local_dir.z;
  // Products of the linear factors, as polynomials in t.
  const double xy0 = x0 * y0, xy1 = x0 * q + y0 * p, xy2 = p * q;
  const double xz0 = x0 * z0, xz1 = x0 * r + z0 * p, xz2 = p * r;
  const double yz0 = y0 * z0, yz1 = y0 * r + z0 * q, yz2 = q * r;
  const double xyz0 = xy0 * z0, xyz1 = xy0 * r + xy1 * z0, xyz2 = xy1 * r + xy2 * z0,
               xyz3 = xy2 * r;
  Cubic s;
  s.c[0] = a + bx * x0 + by * y0 + bz * z0 + exy * xy0 + exz * xz0 + eyz * yz0 + hxyz * xyz0;
  s.c[1] = bx * p + by * q + bz * r + exy * xy1 + exz * xz1 + eyz * yz1 + hxyz * xyz1;
  s.c[2] = exy * xy2 + exz * xz2 + eyz * yz2 + hxyz * xyz2;
  s.c[3] = hxyz * xyz3;
  return s;
}

int gradient_along(const GradientField& gradients, const CellSegment& seg, Vec3 dir, Cubic (&grad)[3],
                   double (&kinks)[3]) {
  for (int a = 0; a < 3; ++a) grad[a] = trilinear_along(gradients.cell_corners(a, seg.cell), seg);
  return sign_changes(combine(1.0, combine(dir.x, grad[0], dir.y, grad[1]), dir.z, grad[2]), seg.tb - seg.ta, kinks);
}

}  // namespace vri
