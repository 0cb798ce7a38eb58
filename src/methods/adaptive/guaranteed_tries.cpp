#include "guaranteed_tries.hpp"

#include "core/f64x4.hpp"
#include "core/simd.hpp"
#include "simpson5.hpp"

namespace vri::simpson5 {

// colour_step (simpson_colour_step.cpp) lane by lane, on the samples, with
// simpson5.hpp's whole(), halves() and corrected() on the lanes (error()
// written out: |D - S| / 15 as a product).
VRI_AVX2_CLONES void PieceTries::run_lanes() {
  using namespace f64x4;
  const V cu[4] = {load(c[0]), load(c[1]), load(c[2]), load(c[3])};
  const V h0 = load(h), u0 = load(u), sr = load(s_ref);
  // The samples: TfSegment::at(s(u + h (k / 4))), channel by channel.
  V v[5][4];
  for (int k = 0; k < 5; ++k) {
    const V p = u0 + h0 * (0.25 * k);
    const V ds = (((cu[3] * p + cu[2]) * p + cu[1]) * p + cu[0]) - sr;
    for (int ch = 0; ch < 4; ++ch) v[k][ch] = load(ref[ch]) + load(slope[ch]) * ds;
  }
  V w[5], e4 = splat(1);
  w[0] = v[0][3];
  for (int k = 1; k < 5; ++k) {
    V sum = kDepthWeights[0][k - 1] * v[0][3];
    for (int j = 1; j < 5; ++j) sum = sum + kDepthWeights[j][k - 1] * v[j][3];
    V depth = sum * (h0 * kDepthScale[k - 1]);
    depth = depth < 0 ? splat(0) : depth;  // as colour_step: the quartic's dip below zero
    const V e = exp_neg(depth);
    w[k] = v[k][3] * e;
    if (k == 4) e4 = e;
  }
  store(attenuation, e4);
  V largest = splat(0);
  for (int ch = 0; ch < 4; ++ch) {
    V g[5];
    for (int k = 0; k < 5; ++k) g[k] = (ch < 3 ? v[k][ch] : splat(1.0)) * w[k];
    const V S = whole(g, h0), D = halves(g, h0);
    const V gap = abs(D - S);
    largest = gap > largest ? gap : largest;
    store(channel_err[ch], gap * kFifteenth);  // error(D, S)
    store(boole[ch], corrected(D, S));
  }
  store(err, largest * kFifteenth);
  const V tau[5] = {v[0][3], v[1][3], v[2][3], v[3][3], v[4][3]};
  store(depth_err, abs(halves(tau, h0) - whole(tau, h0)) * kFifteenth);
}

}  // namespace vri::simpson5
