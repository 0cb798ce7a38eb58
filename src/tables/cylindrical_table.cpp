#include "tables/cylindrical_table.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "vri/error.hpp"

namespace vri {

CylindricalTable::CylindricalTable(const SlabTable& table, int size, int planes)
    : n_(size), planes_(planes), s_lo_(table.axis().s_lo), s_span_(table.axis().s_hi - table.axis().s_lo),
      max_length_(table.max_length()) {
  if (size < 2 || size > 4096) throw Error("cylindrical table size must be in [2, 4096], got " + std::to_string(size));
  if (planes < 2 || planes > 16384)
    throw Error("cylindrical table planes must be in [2, 16384], got " + std::to_string(planes));
  if (double(size) * size * planes > 1 << 26) throw Error("cylindrical table is too large (size^2 * planes > 2^26)");
  tiles_.resize(std::size_t(planes) * n_ * n_ * 4);
  for (int k = 0; k < planes_; ++k) {
    const double a = double(k) / (planes_ - 1);
    for (int i = 0; i < n_; ++i)
      for (int j = 0; j < n_; ++j) {
        const double s = double(i) / (n_ - 1), t = double(j) / (n_ - 1);
        double sf, l;  // equation 9; s_b = t
        if (a <= 0.25) sf = t + s, l = 4 * a * s;
        else if (a <= 0.5) sf = t + 4 * (0.5 - a) * s, l = s;
        else if (a <= 0.75) sf = t - 4 * (a - 0.5) * s, l = s;
        else sf = t - s, l = 4 * (1 - a) * s;
        const Rgba v = table.lookup(l * max_length_, s_lo_ + sf * s_span_, s_lo_ + t * s_span_);
        float* e = &tiles_[((std::size_t(k) * n_ + i) * n_ + j) * 4];
        for (int c = 0; c < 4; ++c) e[c] = static_cast<float>(v[c]);
      }
  }
}

double CylindricalTable::alpha(double l, double s_f, double s_b) const {
  const double d = s_span_ > 0 ? (s_f - s_b) / s_span_ : 0, ln = l / max_length_;
  if (d == 0 && ln == 0) return 0;
  if (d >= ln) return ln / (4 * d);          // [0, .25]
  if (-d >= ln) return 1 + ln / (4 * d);     // [.75, 1]
  return 0.5 - d / (4 * ln);                 // [.25, .75]
}

Rgba CylindricalTable::lookup(double alpha, double l, double s_f, double s_b) const {
  const double d = s_span_ > 0 ? (s_f - s_b) / s_span_ : 0, ln = l / max_length_;
  const double t = s_span_ > 0 ? (s_b - s_lo_) / s_span_ : 0;
  // The radial coordinate on the nearest axis plane: |s_f - s_b| near 0 and 180 degrees, l near 90.
  const double s = (alpha <= 0.25 || alpha >= 0.75) ? std::abs(d) : ln;
  auto cell = [](double x, int n, int& i0, double& w) {
    x = std::clamp(x, 0.0, double(n - 1));
    i0 = std::min(static_cast<int>(x), n - 2);
    w = x - i0;
  };
  int k0, i0, j0;
  double wk, wi, wj;
  cell(alpha * (planes_ - 1), planes_, k0, wk);
  cell(s * (n_ - 1), n_, i0, wi);
  cell(t * (n_ - 1), n_, j0, wj);
  Rgba out{0, 0, 0, 0};
  for (int dk = 0; dk < 2; ++dk)
    for (int di = 0; di < 2; ++di)
      for (int dj = 0; dj < 2; ++dj) {
        const double w = (dk ? wk : 1 - wk) * (di ? wi : 1 - wi) * (dj ? wj : 1 - wj);
        const float* e = &tiles_[((std::size_t(k0 + dk) * n_ + i0 + di) * n_ + j0 + dj) * 4];
        for (int c = 0; c < 4; ++c) out[c] += w * e[c];
      }
  return out;
}

}  // namespace vri
