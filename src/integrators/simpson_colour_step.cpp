#include "simpson_colour_step.hpp"

#include "core/f64x4.hpp"
#include "core/simd.hpp"

namespace vri::simpson5 {

// The scalar form, per channel c and sample k (Campagnolo et al. 2015,
// Algorithm 3's I_O):
//   depth[k] = integral from t to t + k h/4 of the quartic through tau[0..4]
//            = (sum_j W[j][k] tau[j]) ((h/4) / den[k]),
//   g[c][k] = f[k].c (tau[k] e^{-depth[k]})    (at T = 1),
//   S[c] = whole(g[c], h),  D[c] = halves(g[c], h),
// each sum in the order simpson5.hpp writes it, so the lanes give what a
// loop over k and c would. Lane k - 1 holds sample k for the depths and
// weights, then lanes r, g, b, alpha hold the channels for the sums.
VRI_AVX2_CLONES ColourStep colour_step(const TfSample (&f)[5], double h) {
  using namespace f64x4;
  // W and den for depth[1..4] (depth[4] is Boole's rule), a row per sample j.
  static constexpr double kW[5][4] = {
      {251, 29, 27, 14}, {646, 124, 102, 64}, {-264, 24, 72, 24}, {106, 4, 42, 64}, {-19, -1, -3, 14}};
  static constexpr double kDen[4] = {720, 90, 80, 45};
  ColourStep st;
  for (int k = 0; k < 5; ++k) st.tau[k] = f[k].tau;
  V sum = load(kW[0]) * f[0].tau;
  for (int j = 1; j < 5; ++j) sum = sum + load(kW[j]) * f[j].tau;
  // ((h/4)/den is ready before the sum: no division on the samples' path.)
  const V depth = sum * (h / 4 / load(kDen));
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
  const V S = h / 6 * ((g[0] + 4 * g[2]) + g[4]);
  const V D = h / 12 * ((((g[0] + 4 * g[1]) + 2 * g[2]) + 4 * g[3]) + g[4]);
  store(st.S, S);
  store(st.D, D);
  st.err = max_lane(abs(D - S)) / 15;  // = the largest |D - S| / 15: dividing keeps the order
  return st;
}

}  // namespace vri::simpson5
