#pragma once
// Five equally spaced samples f[0..4] of one function on a step [t, t + h]
// give both Simpson estimates of Campagnolo, Celes & de Figueiredo 2015
// (Sec. III, "Simpson's rule"):
//   S(t,h) = h/6 [f(t) + 4 f(t+h/2) + f(t+h)]          (one step)
//   D(t,h) = S(t,h/2) + S(t+h/2,h/2)                    (two half steps)
//   E(t,h) = |D - S| / 15                               (error estimate of D)
// and the accepted value D + (D - S)/15 (Richardson's correction, which is
// Boole's rule). The optical depth inside a step, the quartic through the
// five samples integrated from t to each, is colour_step's
// (simpson_colour_step.cpp).
#include <cmath>

namespace vri::simpson5 {

inline double whole(const double (&f)[5], double h) { return h / 6 * (f[0] + 4 * f[2] + f[4]); }

inline double halves(const double (&f)[5], double h) {
  return h / 12 * (f[0] + 4 * f[1] + 2 * f[2] + 4 * f[3] + f[4]);
}

inline double error(double d, double s) { return std::abs(d - s) / 15; }

inline double corrected(double d, double s) { return d + (d - s) / 15; }

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
