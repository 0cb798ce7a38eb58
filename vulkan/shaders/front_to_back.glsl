// Front-to-back compositing in double-float (double_float.glsl), as the
// CPU's FrontToBack composites in double (src/methods/march/ray_steps.hpp):
// each sample's or slab's value is float, the running colour C and
// transmittance T about 48 bits. In float they rounded once a slab, which
// grows over the thousands of slabs of a fine step (4e-5 on engine with
// riemann at h = 0.02, against the double path). Needs only fma-free float
// arithmetic, as the rest of double_float.glsl.

struct FrontToBack {
  DF r, g, b, T;
};

FrontToBack ftb_start() { return FrontToBack(DF(0.0, 0.0), DF(0.0, 0.0), DF(0.0, 0.0), DF(1.0, 0.0)); }

// a * b for a float b.
DF df_mul_f(DF a, float b) {
  DF p = df_two_prod(a.hi, b);
  precise float lo = p.lo + a.lo * b;
  return df_fast_two_sum(p.hi, lo);
}

// A slab's premultiplied colour and opacity (r, g, b, alpha) in double-float:
// C += T c, T *= 1 - alpha.
void ftb_add_df(inout FrontToBack acc, DF v[4]) {
  acc.r = df_add(acc.r, df_mul(acc.T, v[0]));
  acc.g = df_add(acc.g, df_mul(acc.T, v[1]));
  acc.b = df_add(acc.b, df_mul(acc.T, v[2]));
  acc.T = df_mul(acc.T, df_sub(DF(1.0, 0.0), v[3]));
}

// The same for a float slab v.
void ftb_add(inout FrontToBack acc, vec4 v) {
  DF d[4] = DF[4](DF(v.r, 0.0), DF(v.g, 0.0), DF(v.b, 0.0), DF(v.a, 0.0));
  ftb_add_df(acc, d);
}

// A Riemann step: colour c over a step of transparency e: w = T (1 - e), C += w c, T *= e.
void ftb_add_step(inout FrontToBack acc, vec3 c, float e) {
  const DF w = df_mul(acc.T, df_two_sum(1.0, -e));
  acc.r = df_add(acc.r, df_mul_f(w, c.r));
  acc.g = df_add(acc.g, df_mul_f(w, c.g));
  acc.b = df_add(acc.b, df_mul_f(w, c.b));
  acc.T = df_mul_f(acc.T, e);
}

bool ftb_below(FrontToBack acc, DF termination) { return df_less(acc.T, termination); }

vec4 ftb_pixel(FrontToBack acc) {
  return vec4(df_float(acc.r), df_float(acc.g), df_float(acc.b), df_float(df_sub(DF(1.0, 0.0), acc.T)));
}
