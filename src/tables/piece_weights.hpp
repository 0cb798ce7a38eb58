#pragma once
// PieceWeights: how one piece of a slab (tau and c linear in t, optical
// thicknesses A = tau_p d at the front end p and B = tau_q d at the back end
// q) turns colours into premultiplied colour, in both directions:
//   C_forward  = c_p fp + c_q fq,  C_backward = c_q bq + c_p bp,  alpha = 1 - E,
// with E = exp(-(A+B)/2), J(A,B) = int_0^1 exp(-A x - (B-A) x^2 / 2) dx and
//   fp = 1 - J(A,B), fq = J(A,B) - E,  bq = 1 - J(B,A), bp = J(B,A) - E
// (integration by parts, docs/PREINTEGRATION.md §2).
#include <algorithm>

namespace vri {

// T is double, or a GCC vector of doubles for several pieces at once (the
// same IEEE operations lane by lane, so the same bits).
template <class T>
struct BasicPieceWeights {
  T fp{}, fq{}, bq{}, bp{}, alpha{};
};
using PieceWeights = BasicPieceWeights<double>;

namespace piece_series {

// Thin pieces (A, B <= kThin): J as a double series, no exponentials. With
// sigma = (A+B)/2, delta = (B-A)/2 the forward depth is sigma x - delta x(1-x), so
//   J(sigma, +-delta) = sum_ij c[j][i] sigma^i (+-delta)^j,
//   c[j][i] = (-1)^i int_0^1 x^i (x(1-x))^j dx / (i! j!) = (-1)^i (i+j)! / (i! (i+2j+1)!),
// the backward J being the same series with delta -> -delta. Terms with
// j >= 1 up to total degree kP (first dropped term < 0.125^7 / 8! < 1e-11);
// j = 0 alone carries 1 - E and runs to degree kP0 (< 0.125^10 / 11! < 1e-16).
inline constexpr double kThin = 0.125;
inline constexpr int kP = 6, kP0 = 9;

constexpr double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }
struct Coefficients {
  double c[kP + 1][kP + 1] = {};
  // j = 0 without the constant: J0 - 1 (coefficients c[0][i]) and J0 - E
  // ((-1)^(i+1) i / (i+1)!), i = 1 .. kP0, so no weight suffers cancellation.
  double j0m1[kP0 + 1] = {}, j0me[kP0 + 1] = {};
  constexpr Coefficients() {
    for (int j = 1; j <= kP; ++j)
      for (int i = 0; i + j <= kP; ++i)
        c[j][i] = (i % 2 ? -1 : 1) * factorial(i + j) / (factorial(i) * factorial(i + 2 * j + 1));
    for (int i = 1; i <= kP0; ++i) {
      j0m1[i] = (i % 2 ? -1 : 1) / factorial(i + 1);
      j0me[i] = (i % 2 ? 1 : -1) * i / factorial(i + 1);
    }
  }
};
inline constexpr Coefficients kC;

template <int j, class T>
inline T poly(T sigma) {  // sum_i c[j][i] sigma^i, Horner
  T v{};
  for (int i = kP - j; i >= 0; --i) v = v * sigma + kC.c[j][i];
  return v;
}

}  // namespace piece_series

// Inline so the table builders' inner loops can vectorise it. A, B <= kThin.
template <class T>
inline BasicPieceWeights<T> thin_piece_weights(T A, T B) {
  using namespace piece_series;
  const T sigma = 0.5 * (A + B), delta = 0.5 * (B - A), d2 = delta * delta;
  T j0m1{}, j0me{};
#pragma GCC unroll 16
  for (int i = kP0; i >= 1; --i) {
    j0m1 = (j0m1 + kC.j0m1[i]) * sigma;
    j0me = (j0me + kC.j0me[i]) * sigma;
  }
  static_assert(kP == 6);
  const T even = d2 * (poly<2>(sigma) + d2 * (poly<4>(sigma) + d2 * poly<6>(sigma)));
  const T odd = delta * (poly<1>(sigma) + d2 * (poly<3>(sigma) + d2 * poly<5>(sigma)));
  return {-(j0m1 + even) - odd, j0me + even + odd, -(j0m1 + even) + odd, j0me + even - odd, j0me - j0m1};
}

// Any thickness: the series when thin, else J by 6-point Gauss-Legendre on
// panels of optical depth <= 1 (relative error below 1e-12), the backward J
// reusing the forward exponentials (piece_weights.cpp).
PieceWeights thick_piece_weights(double A, double B);
inline PieceWeights piece_weights(double A, double B) {
  return std::max(A, B) <= piece_series::kThin ? thin_piece_weights(A, B) : thick_piece_weights(A, B);
}

}  // namespace vri
