#pragma once
// Five equally spaced samples f[0..4] of one function on a step [t, t + h]
// give both Simpson estimates of Campagnolo, Celes & de Figueiredo 2015
// (Sec. III, "Simpson's rule"):
//   S(t,h) = h/6 [f(t) + 4 f(t+h/2) + f(t+h)]          (one step)
//   D(t,h) = S(t,h/2) + S(t+h/2,h/2)                    (two half steps)
//   E(t,h) = |D - S| / 15                               (error estimate of D)
// and the accepted value D + (D - S)/15 (Richardson's correction, which is
// Boole's rule).
#include <cmath>

namespace vri::simpson5 {

// The constant divisors as products by their reciprocals (a division costs
// several multiplications on the tries' path).
inline constexpr double kSixth = 1.0 / 6, kTwelfth = 1.0 / 12, kFifteenth = 1.0 / 15;

// The optical depth inside a step: depth[k], the integral from t to
// t + k h/4 of the quartic through the five tau samples, is
// (sum_j kDepthWeights[j][k - 1] tau[j]) h kDepthScale[k - 1] for k = 1..4
// (depth[4] is Boole's rule), a row per sample j.
inline constexpr double kDepthWeights[5][4] = {
    {251, 29, 27, 14}, {646, 124, 102, 64}, {-264, 24, 72, 24}, {106, 4, 42, 64}, {-19, -1, -3, 14}};
inline constexpr double kDepthScale[4] = {1.0 / 2880, 1.0 / 360, 1.0 / 320, 1.0 / 180};  // 1 / (4 x 720, 90, 80, 45)

// On doubles, and on the lanes of core/f64x4.hpp's vectors (samples T, step
// H a double or lanes too) in the same order, so that the vector tries give
// the bytes of the scalar ones.
template <class T, class H>
inline T whole(const T (&f)[5], H h) { return h * kSixth * (f[0] + 4 * f[2] + f[4]); }

template <class T, class H>
inline T halves(const T (&f)[5], H h) {
  return h * kTwelfth * (f[0] + 4 * f[1] + 2 * f[2] + 4 * f[3] + f[4]);
}

inline double error(double d, double s) { return std::abs(d - s) * kFifteenth; }

template <class T>
inline T corrected(T d, T s) { return d + (d - s) * kFifteenth; }

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
