// SPEC §5 shading as the CPU float paths compute it
// (src/methods/march/float_shading.hpp): c_lit = c a + b with a = ka + kd x,
// b = ks x^p, x = |N . d|; x^p as exp(p ln x) by the CPU's own polynomials
// (float_math.hpp). The gradient comes from the caller (grids:
// grid_sampler.glsl's gradient_at). Needs before it: exp_neg.glsl, and in
// `p`: ka, kd, ks, shininess, flat_threshold.

struct Terms {
  float a, b;
};

// ln x for normal floats x (Cephes' logf, as log_pos on the CPU).
float log_pos(float x) {
  const float kSqrtHalf = 0.707106781186547524, kMin = 1.17549435e-38;
  const uint bits = floatBitsToUint(max(x, kMin));
  precise float e = float(int(bits >> 23) - 126);
  precise float m = uintBitsToFloat((bits & 0x807fffffu) | 0x3f000000u);
  if (m < kSqrtHalf) {
    e = e - 1.0;
    m = (m + m) - 1.0;
  } else {
    m = m - 1.0;
  }
  precise float z = m * m;
  precise float y = 7.0376836292e-2;
  y = y * m + -1.1514610310e-1;
  y = y * m + 1.1676998740e-1;
  y = y * m + -1.2420140846e-1;
  y = y * m + 1.4249322787e-1;
  y = y * m + -1.6668057665e-1;
  y = y * m + 2.0000714765e-1;
  y = y * m + -2.4999993993e-1;
  y = y * m + 3.3333331174e-1;
  y = (y * m) * z;
  y = y + e * -2.12194440e-4;
  y = y - 0.5 * z;
  precise float r = (m + y) + e * 0.693359375;
  return r;
}

float pow_unit(float x, float q) {
  precise float l = q * log_pos(x);
  return exp_neg(-l);
}

// The terms of gradient g seen along d; no normal (|g| under the flat
// threshold): a = ka + kd, b = 0.
Terms terms_of(vec3 g, vec3 d) {
  precise float len = sqrt((g.x * g.x + g.y * g.y) + g.z * g.z);
  if (!(len >= p.flat_threshold) || len == 0.0) {
    precise float a0 = p.ka + p.kd;
    return Terms(a0, 0.0);
  }
  precise float x = abs((g.x * d.x + g.y * d.y) + g.z * d.z) / len;
  precise float a = p.ka + p.kd * x;
  precise float b = p.ks * pow_unit(x, p.shininess);
  return Terms(a, b);
}
