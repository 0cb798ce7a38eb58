// The trilinear field along a ray inside one cell as a cubic in t, and what
// the guaranteed adaptive march needs of it, as src/methods/exact/cubic.cpp
// computes it on the CPU (in float here): c.x + c.y t + c.z t^2 + c.w t^3.

float cubic_at(vec4 c, float t) { return ((c.w * t + c.z) * t + c.y) * t + c.x; }
float cubic_slope(vec4 c, float t) { return (3.0 * c.w * t + 2.0 * c.z) * t + c.y; }

// The trilinear interpolant of the corners v (c000, c100, c010, c110, c001,
// c101, c011, c111) along x(t) = x0 + dir t, by substituting the linear
// factors into a + b x + c y + d z + e xy + f xz + g yz + h xyz.
vec4 trilinear_along(float v[8], vec3 x0, vec3 dir) {
  const float a = v[0], bx = v[1] - v[0], by = v[2] - v[0], bz = v[4] - v[0];
  const float exy = ((v[3] - v[1]) - v[2]) + v[0];
  const float exz = ((v[5] - v[1]) - v[4]) + v[0];
  const float eyz = ((v[6] - v[2]) - v[4]) + v[0];
  const float hxyz = ((((((v[7] - v[3]) - v[5]) - v[6]) + v[1]) + v[2]) + v[4]) - v[0];
  const float p = dir.x, q = dir.y, r = dir.z;
  const float xy0 = x0.x * x0.y, xy1 = x0.x * q + x0.y * p, xy2 = p * q;
  const float xz0 = x0.x * x0.z, xz1 = x0.x * r + x0.z * p, xz2 = p * r;
  const float yz0 = x0.y * x0.z, yz1 = x0.y * r + x0.z * q, yz2 = q * r;
  const float xyz0 = xy0 * x0.z, xyz1 = xy0 * r + xy1 * x0.z, xyz2 = xy1 * r + xy2 * x0.z, xyz3 = xy2 * r;
  vec4 s;
  s.x = a + bx * x0.x + by * x0.y + bz * x0.z + exy * xy0 + exz * xz0 + eyz * yz0 + hxyz * xyz0;
  s.y = bx * p + by * q + bz * r + exy * xy1 + exz * xz1 + eyz * yz1 + hxyz * xyz1;
  s.z = exy * xy2 + exz * xz2 + eyz * yz2 + hxyz * xyz2;
  s.w = hxyz * xyz3;
  return s;
}

// The critical points strictly inside (0, len), ascending; returns how many.
int critical_points(vec4 c, float len, out float crit[2]) {
  const float a = 3.0 * c.w, b = 2.0 * c.z, cc = c.y;  // s' = a t^2 + b t + cc
  float r[2];
  int n = 0;
  if (a == 0.0) {
    if (b != 0.0) r[n++] = -cc / b;
  } else {
    const float disc = b * b - 4.0 * a * cc;
    if (disc >= 0.0) {
      const float q = -0.5 * (b + (b < 0.0 ? -sqrt(disc) : sqrt(disc)));  // cancellation-free
      if (q != 0.0) {
        r[n++] = q / a;
        r[n++] = cc / q;
      } else {
        r[n++] = 0.0;
      }
    }
  }
  int m = 0;
  for (int i = 0; i < n; ++i)
    if (r[i] > 0.0 && r[i] < len) crit[m++] = r[i];
  if (m == 2 && crit[0] > crit[1]) crit = float[2](crit[1], crit[0]);
  if (m == 2 && crit[0] == crit[1]) m = 1;
  return m;
}

// The t in [lo, hi] where c, monotone there, equals value (strictly between
// its end values): Newton's method inside a shrinking bracket, bisection when
// it strays.
float solve_monotone(vec4 c, float value, float lo, float hi) {
  const bool increasing = cubic_at(c, lo) - value < 0.0;
  float x = 0.5 * (lo + hi);
  for (int it = 0; it < 60; ++it) {
    const float fx = cubic_at(c, x) - value;
    if (fx == 0.0) return x;
    if ((fx < 0.0) == increasing) lo = x; else hi = x;
    const float d = cubic_slope(c, x);
    float xn = d != 0.0 ? x - fx / d : 0.5 * (lo + hi);
    if (!(xn > lo && xn < hi)) xn = 0.5 * (lo + hi);
    if (abs(xn - x) <= 2e-7 * max(1.0, abs(x)) || hi - lo <= 2e-7 * max(1.0, abs(hi))) return xn;
    x = xn;
  }
  return x;
}

// The roots inside (0, len) where c changes sign, ascending; returns how many.
int sign_changes(vec4 c, float len, out float roots[3]) {
  float knots[4], crit[2];
  const int nc = critical_points(c, len, crit);
  knots[0] = 0.0;
  for (int i = 0; i < nc; ++i) knots[1 + i] = crit[i];
  knots[1 + nc] = len;
  int n = 0;
  for (int m = 0; m < nc + 1; ++m) {
    const float fa = cubic_at(c, knots[m]), fb = cubic_at(c, knots[m + 1]);
    if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0)) roots[n++] = solve_monotone(c, 0.0, knots[m], knots[m + 1]);
  }
  return n;
}
