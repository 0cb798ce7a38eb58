#version 450
// A first-order pre-integration table on the GPU by Roettger & Ertl 2002, §3
// ("hardware-accelerated pre-integration"), as SlicedBuilder
// (src/tables/sliced_builder.hpp) computes it on the CPU: one
// invocation per entry (s_f, s_b) - their rasterised rectangle - walks the
// n steps of length l/n back to front, step k sampling the transfer function
// at s = s_f + (s_b - s_f)(k + 1/2)/n and blending the Stein et al. slab of
// their eq. 8:
//   alpha = 1 - exp(-tau(s) l/n),  C <- c(s) alpha + (1 - alpha) C,  T <- (1 - alpha) T,
// with float32 accumulation (the CPU's `fp32`; its double products are
// float products here). One dispatch per table length, `base` its first entry.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;

#include "table_builder_push_constants.h"
layout(push_constant) uniform Params { VRI_SLICED_TABLE_PUSH_CONSTANTS } p;

#include "split_array.glsl"
SPLIT_OUTPUT(vec4, entries, 0, 4u)
#define DISCRETE_TF_BINDING 4
#include "discrete_tf.glsl"
#include "exp_neg.glsl"

// floor(a / b) for b > 0.
int floor_div(int a, int b) {
  const int q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}

void main() {
  const int b = int(gl_GlobalInvocationID.x), f = int(gl_WorkGroupID.y);
  if (b >= p.table_n) return;
  // Step k samples u = f + d (2k + 1) / (2n), d = b - f, kept exactly as
  // f + q + r / (2n) with integers q, r (0 <= r < 2n), so the sample's place
  // in its bin is one float division away from the CPU's: a spike narrower
  // than a bin is met where the CPU meets it.
  const int d = b - f, den = 2 * p.steps;
  int q = d + floor_div(-d, den), r = -d - floor_div(-d, den) * den;  // k = n - 1
  const int dq = floor_div(2 * d, den), dr = 2 * d - dq * den;      // k -> k - 1 subtracts 2d
  precise vec3 C = vec3(0.0);
  precise float T = 1.0;
  for (int k = p.steps - 1; k >= 0; --k) {  // back to front
    const vec4 v = at_index(f + q, float(r) / float(den));
    r -= dr;
    q -= dq;
    if (r < 0) r += den, q -= 1;
    precise float x = v.w * p.dl;
    const float a = one_minus_exp_neg(x);
    // (1 - a) X as X - a X: 1 - a in float would keep few of a small a's bits.
    C = v.rgb * a + (C - a * C);
    T = T - a * T;
  }
  entries_put(p.base + uint(f * p.table_n + b), vec4(C, 1.0 - T));
}
