#pragma once
// Five equally spaced samples f[0..4] of one function on a step [t, t + h]
// give both Simpson estimates of Campagnolo, Celes & de Figueiredo 2015
// (Sec. III, "Simpson's rule"):
//   S(t,h) = h/6 [f(t) + 4 f(t+h/2) + f(t+h)]          (one step)
//   D(t,h) = S(t,h/2) + S(t+h/2,h/2)                    (two half steps)
//   E(t,h) = |D - S| / 15                               (error estimate of D)
// and the accepted value D + (D - S)/15 (Richardson's correction, which is
// Boole's rule). cumulative() integrates the quartic through the five samples
// from t to each sample, for the optical depth inside a step.
#include <cmath>

namespace vri::simpson5 {

inline double whole(const double (&f)[5], double h) { return h / 6 * (f[0] + 4 * f[2] + f[4]); }

inline double halves(const double (&f)[5], double h) {
  return h / 12 * (f[0] + 4 * f[1] + 2 * f[2] + 4 * f[3] + f[4]);
}

inline double error(double d, double s) { return std::abs(d - s) / 15; }

inline double corrected(double d, double s) { return d + (d - s) / 15; }

// out[k] = integral from t to t + k h/4 of the quartic interpolating f (out[4]
// is Boole's rule, equal to corrected(halves, whole) up to rounding).
inline void cumulative(const double (&f)[5], double h, double (&out)[5]) {
  const double q = h / 4;
  out[0] = 0;
  out[1] = q * (251 * f[0] + 646 * f[1] - 264 * f[2] + 106 * f[3] - 19 * f[4]) / 720;
  out[2] = q * (29 * f[0] + 124 * f[1] + 24 * f[2] + 4 * f[3] - f[4]) / 90;
  out[3] = q * (27 * f[0] + 102 * f[1] + 72 * f[2] + 42 * f[3] - 3 * f[4]) / 80;
  out[4] = q * (14 * f[0] + 64 * f[1] + 24 * f[2] + 64 * f[3] + 14 * f[4]) / 45;
}

// Algorithm 2's step control: halve the step (and with it the tolerance) on a
// failed try; double both after the second consecutive success; keep the step
// in [hmin, hmax].
struct StepControl {
  double h;
  bool last_succeeded = true;
  void succeeded(double hmax) {
    if (last_succeeded) h = std::fmin(2 * h, hmax);
    last_succeeded = true;
  }
  void failed(double h_tried, double hmin) {
    h = std::fmax(h_tried / 2, hmin);
    last_succeeded = false;
  }
};

}  // namespace vri::simpson5
