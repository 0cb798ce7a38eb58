// SPEC §5 shading as the CPU float paths compute it
// (src/integrators/float_shading.hpp): the gradient interpolated
// trilinearly from the host's gradient field in the sample's cell, and
// c_lit = c a + b with a = ka + kd x, b = ks x^p, x = |N . d|; x^p as
// exp(p ln x) by the CPU's own polynomials (float_math.hpp). Needs before
// it: buffer Gradients { float g[]; } gradients (three floats a grid point),
// exp_neg.glsl, and in `p`: ka, kd, ks, shininess, flat_threshold.

struct Terms {
  float a, b;
};

vec3 gradient_at(Cell c) {
  const uint o = 3u * c.offset, y = 3u * p.sy, z = 3u * p.sz;
  vec3 out_g;
  for (int a = 0; a < 3; ++a) {
    const uint i = o + uint(a);
    const float v0 = gradients.g[i], v1 = gradients.g[i + 3u], v2 = gradients.g[i + y], v3 = gradients.g[i + y + 3u];
    const float v4 = gradients.g[i + z], v5 = gradients.g[i + z + 3u], v6 = gradients.g[i + z + y];
    const float v7 = gradients.g[i + z + y + 3u];
    precise float c00 = v0 + c.f.x * (v1 - v0);
    precise float c10 = v2 + c.f.x * (v3 - v2);
    precise float c01 = v4 + c.f.x * (v5 - v4);
    precise float c11 = v6 + c.f.x * (v7 - v6);
    precise float c0 = c00 + c.f.y * (c10 - c00);
    precise float c1 = c01 + c.f.y * (c11 - c01);
    precise float g = c0 + c.f.z * (c1 - c0);
    out_g[a] = g;
  }
  return out_g;
}

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
