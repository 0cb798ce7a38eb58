#pragma once
// One try of the outer integral (I_O of Campagnolo, Celes & de Figueiredo
// 2015, Algorithm 3) on five equally spaced samples of a step [t, t + h]:
// r, g, b and alpha of SPEC §4 (c tau T e^{-depth}, with c already lit where
// lighting is on) by both Simpson estimates, and the optical depth inside the
// step from the quartic through the tau samples. Shared by the paper's
// strategies and the guaranteed one.
//
// The try is made at T = 1: every sum is linear in the transmittance T at t,
// so the caller scales the errors by T (add_step scales the colour), and a
// try does not wait for the steps before it (guaranteed_tries.hpp makes four
// at once).
#include <cmath>

#include "simpson5.hpp"
#include "vri/transfer_function.hpp"

namespace vri::simpson5 {

// The sample with its chromaticity lit (SPEC §5): c_lit = c a + b.
inline TfSample lit(TfSample v, double a, double b) {
  return {v.r * a + b, v.g * a + b, v.b * a + b, v.tau};
}

struct ColourStep {
  double tau[5], depth[5];  // tau at the samples; optical depth from t to each
  double attenuation;       // e^{-depth[4]}: the step's transmittance
  double S[4], D[4];        // whole and halves, per channel r, g, b, alpha, at T = 1
  double err;               // the largest error(D, S) over the channels, at T = 1
};

// Four lanes at a time (core/f64x4.hpp): the depths and their exponentials
// over the samples 1..4, then the Simpson sums over the channels r, g, b,
// alpha; the same bytes on every target (simpson_colour_step.cpp).
ColourStep colour_step(const TfSample (&f)[5], double h);

// Adds an accepted step to the premultiplied colour C and returns the
// transmittance after it. Opacity is 1 - T with T = exp(-optical depth) (SPEC
// §4): the step's opacity is T (1 - e^{-depth}) exactly for its optical depth,
// not the Simpson estimate of the fourth channel (which an under-resolved
// step can push past 1). The step's colour is its Boole estimate rescaled to
// that opacity: Boole's weights are positive, so the colour is a weighted mean
// of the samples' (lit) chromaticities times the opacity, never more than the
// brightest sample times it. On an accurate step the rescaling is ~1.
inline double add_step(double attenuation, const double (&corrected)[4], double T, double (&C)[3]) {
  const double T_after = T * attenuation;
  const double opacity = T - T_after;
  const double scale = corrected[3] > 0 ? opacity / corrected[3] : 0;  // T drops out: corrected is at T = 1
  for (int c = 0; c < 3; ++c) C[c] += scale * corrected[c];
  return T_after;
}
inline double add_step(const ColourStep& st, double T, double (&C)[3]) {
  double boole[4];
  for (int c = 0; c < 4; ++c) boole[c] = corrected(st.D[c], st.S[c]);
  return add_step(st.attenuation, boole, T, C);
}

}  // namespace vri::simpson5
