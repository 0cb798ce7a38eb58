// One try of the outer integral on the five samples f (r, g, b lit, tau) of
// a step [t, t + h], as src/methods/adaptive/simpson_colour_step.hpp computes it
// (Campagnolo, Celes & de Figueiredo 2015, Algorithm 3, in float): the
// optical depth from t to each sample from the quartic through the tau
// samples, then r, g, b and alpha (c tau T e^{-depth}) by Simpson's rule over
// the whole step (S) and its two halves (D). Needs before it: exp_neg.glsl.

// The error estimate |D - S| / 15 of the inner integral (the optical
// depth) on the same five samples.
float tau_error(vec4 f[5], float h) {
  const float whole = h / 6.0 * (f[0].w + 4.0 * f[2].w + f[4].w);
  const float halves = h / 12.0 * (f[0].w + 4.0 * f[1].w + 2.0 * f[2].w + 4.0 * f[3].w + f[4].w);
  return abs(halves - whole) / 15.0;
}

struct ColourStep {
  vec4 S, D;
  float attenuation;  // e^{-depth} over the whole step
};

ColourStep colour_step(vec4 f[5], float T, float h) {
  const float q = h / 4.0;
  float depth[5];
  depth[0] = 0.0;
  depth[1] = q * (251.0 * f[0].w + 646.0 * f[1].w - 264.0 * f[2].w + 106.0 * f[3].w - 19.0 * f[4].w) / 720.0;
  depth[2] = q * (29.0 * f[0].w + 124.0 * f[1].w + 24.0 * f[2].w + 4.0 * f[3].w - f[4].w) / 90.0;
  depth[3] = q * (27.0 * f[0].w + 102.0 * f[1].w + 72.0 * f[2].w + 42.0 * f[3].w - 3.0 * f[4].w) / 80.0;
  depth[4] = q * (14.0 * f[0].w + 64.0 * f[1].w + 24.0 * f[2].w + 64.0 * f[3].w + 14.0 * f[4].w) / 45.0;
  vec4 g[5];
  ColourStep st;
  for (int k = 0; k < 5; ++k) {
    depth[k] = max(depth[k], 0.0);  // the quartic can dip below zero (simpson_colour_step.cpp)
    const float e = exp_neg(depth[k]);
    if (k == 4) st.attenuation = e;
    const float w = f[k].w * T * e;
    g[k] = vec4(f[k].rgb * w, w);
  }
  st.S = h / 6.0 * (g[0] + 4.0 * g[2] + g[4]);
  st.D = h / 12.0 * (g[0] + 4.0 * g[1] + 2.0 * g[2] + 4.0 * g[3] + g[4]);
  return st;
}

// The largest error estimate |D - S| / 15 over the channels.
float colour_error(ColourStep st) {
  const vec4 E = abs(st.D - st.S) / 15.0;
  return max(max(E.x, E.y), max(E.z, E.w));
}

// Adds an accepted step to C and returns the transmittance after it: the
// step's opacity exactly for its optical depth, its colour Boole's estimate
// rescaled to that opacity (add_step).
float add_step(ColourStep st, float T, inout vec3 C) {
  const float T_after = T * st.attenuation;
  const vec4 boole = st.D + (st.D - st.S) / 15.0;
  const float scale = boole.w > 0.0 ? (T - T_after) / boole.w : 0.0;
  C += scale * boole.rgb;
  return T_after;
}
