#include "simpson_colour_step.hpp"

#include "core/f64x4.hpp"
#include "core/simd.hpp"

namespace vri::simpson5 {

// The scalar form, per channel c and sample k (Campagnolo et al. 2015,
// Algorithm 3's I_O):
//   depth[k] = integral from t to t + k h/4 of the quartic through tau[0..4]
//            (simpson5.hpp, kDepthWeights),
//   g[c][k] = f[k].c (tau[k] e^{-depth[k]})    (at T = 1),
//   S[c] = whole(g[c], h),  D[c] = halves(g[c], h),
// each sum in the order simpson5.hpp writes it, so the lanes give what a
// loop over k and c would. Lane k - 1 holds sample k for the depths and
// weights, then lanes r, g, b, alpha hold the channels for the sums.
VRI_AVX2_CLONES ColourStep colour_step(const TfSample (&f)[5], double h) {
  using namespace f64x4;
  ColourStep st;
  for (int k = 0; k < 5; ++k) st.tau[k] = f[k].tau;
  V sum = load(kDepthWeights[0]) * f[0].tau;
  for (int j = 1; j < 5; ++j) sum = sum + load(kDepthWeights[j]) * f[j].tau;
  // The quartic through the tau samples can dip below zero between them
  // (a sample at 1e15 beside zeros): a negative depth made e^{+708}, times
  // tau an infinity and the sums NaN (issue 46). The depth is >= 0.
  V depth = sum * (h * load(kDepthScale));
  depth = depth < 0 ? splat(0) : depth;
  st.depth[0] = 0;
  store(st.depth + 1, depth);
  const V e = exp_neg(depth);
  st.attenuation = e[3];
  // (Vectors built from scalar loads: the caller stored f as scalars, which
  // a 32-byte load of them would wait for.)
  const V w = V{f[1].tau, f[2].tau, f[3].tau, f[4].tau} * e;
  const double wk[5] = {f[0].tau, w[0], w[1], w[2], w[3]};  // e^0 = 1
  V g[5];
  for (int k = 0; k < 5; ++k) g[k] = V{f[k].r, f[k].g, f[k].b, 1.0} * wk[k];
  const V S = whole(g, h), D = halves(g, h);
  store(st.S, S);
  store(st.D, D);
  st.err = max_lane(abs(D - S)) * kFifteenth;  // = the largest error(D, S): scaling keeps the order
  return st;
}

}  // namespace vri::simpson5
