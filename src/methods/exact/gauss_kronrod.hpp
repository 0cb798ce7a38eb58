#pragma once
// The 15-point Gauss-Kronrod rule with its embedded 7-point Gauss rule
// (nodes and weights of QUADPACK's qk15). |K15 - G7| estimates the error.
#include <array>

namespace vri::gk15 {

// Kronrod abscissae on [-1, 1] (positive half, descending; the last is 0).
inline constexpr std::array<double, 8> kNodes = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
inline constexpr std::array<double, 8> kKronrodWeights = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
// Gauss weights for the odd Kronrod nodes 1, 3, 5 and the centre 7.
inline constexpr std::array<double, 4> kGaussWeights = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

// Applies the rule to f on [a, b]; f(t, out) writes N values. Returns the
// Kronrod estimate in `k` and |K - G| (max over components) as the error.
template <int N, class F>
double apply(F&& f, double a, double b, double (&k)[N]) {
  const double centre = 0.5 * (a + b), half = 0.5 * (b - a);
  double g[N], v[N], w[N];
  f(centre, v);
  for (int c = 0; c < N; ++c) {
    k[c] = kKronrodWeights[7] * v[c];
    g[c] = kGaussWeights[3] * v[c];
  }
  for (int i = 0; i < 7; ++i) {
    const double dx = half * kNodes[i];
    f(centre - dx, v);
    f(centre + dx, w);
    for (int c = 0; c < N; ++c) {
      const double sum = v[c] + w[c];
      k[c] += kKronrodWeights[i] * sum;
      if (i % 2 == 1) g[c] += kGaussWeights[i / 2] * sum;
    }
  }
  double err = 0;
  for (int c = 0; c < N; ++c) {
    k[c] *= half;
    g[c] *= half;
    const double e = k[c] > g[c] ? k[c] - g[c] : g[c] - k[c];
    err = e > err ? e : err;
  }
  return err;
}

}  // namespace vri::gk15
