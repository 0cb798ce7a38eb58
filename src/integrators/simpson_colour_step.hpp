#pragma once
// One try of the outer integral (I_O of Campagnolo, Celes & de Figueiredo
// 2015, Algorithm 3) on five equally spaced samples of a step [t, t + h]:
// r, g, b and alpha of SPEC §4 (c tau T e^{-depth}, with c already lit where
// lighting is on) by both Simpson estimates, and the optical depth inside the
// step from the quartic through the tau samples. Shared by the paper's
// strategies and the guaranteed one.
#include <algorithm>
#include <cmath>

#include "simpson5.hpp"
#include "vri/transfer/transfer_function.hpp"

namespace vri::simpson5 {

// The sample with its chromaticity lit (SPEC §5): c_lit = c a + b.
inline TfSample lit(TfSample v, double a, double b) {
  return {v.r * a + b, v.g * a + b, v.b * a + b, v.tau};
}

struct ColourStep {
  double tau[5], depth[5];  // tau at the samples; optical depth from t to each
  double attenuation;       // e^{-depth[4]}: the step's transmittance
  double S[4], D[4];        // whole and halves, per channel r, g, b, alpha
  double err;               // the largest error(D, S) over the channels
};

// T: transmittance at t.
inline ColourStep colour_step(const TfSample (&f)[5], double T, double h) {
  ColourStep st;
  for (int k = 0; k < 5; ++k) st.tau[k] = f[k].tau;
  cumulative(st.tau, h, st.depth);
  double g[4][5];
  for (int k = 0; k < 5; ++k) {
    // depth[0] is 0 (e^0 = 1 exactly); e^{-depth[4]} is kept for add_step.
    const double e = k == 0 ? 1.0 : std::exp(-st.depth[k]);
    if (k == 4) st.attenuation = e;
    const double w = f[k].tau * T * e;
    g[0][k] = f[k].r * w;
    g[1][k] = f[k].g * w;
    g[2][k] = f[k].b * w;
    g[3][k] = w;
  }
  st.err = 0;
  for (int c = 0; c < 4; ++c) {
    st.S[c] = whole(g[c], h);
    st.D[c] = halves(g[c], h);
    st.err = std::max(st.err, error(st.D[c], st.S[c]));
  }
  return st;
}

// Adds an accepted step to the premultiplied colour C and returns the
// transmittance after it. Opacity is 1 - T with T = exp(-optical depth) (SPEC
// §4): the step's opacity is T (1 - e^{-depth}) exactly for its optical depth,
// not the Simpson estimate of the fourth channel (which an under-resolved
// step can push past 1). The step's colour is its Boole estimate rescaled to
// that opacity: Boole's weights are positive, so the colour is a weighted mean
// of the samples' (lit) chromaticities times the opacity, never more than the
// brightest sample times it. On an accurate step the rescaling is ~1.
inline double add_step(const ColourStep& st, double T, double (&C)[3]) {
  const double T_after = T * st.attenuation;
  const double opacity = T - T_after;
  const double boole_opacity = corrected(st.D[3], st.S[3]);
  const double scale = boole_opacity > 0 ? opacity / boole_opacity : 0;
  for (int c = 0; c < 3; ++c) C[c] += scale * corrected(st.D[c], st.S[c]);
  return T_after;
}

}  // namespace vri::simpson5
