#version 450
// El Hajjar et al. 2008's second-order table on the GPU (their §6.2 builds
// it in graphics hardware), as FastSecondOrderBuilder
// (src/tables/second_order_fast.hpp) computes it on the CPU: entry
// (s_f, s_m, s_b) walks the parabola through its three scalars (their eq. 2)
// in K chords, each the bilinear lookup of the first-order table of length
// L/K at its two ends, composited front to back. One invocation per entry.
// The chord ends are found in exact integer arithmetic: with d1 = m - f and
// d2 = b - f the parabola is f + q(t), q(t) = (A t + B) t, A = 2 d2 - 4 d1,
// B = 4 d1 - d2, so at t = j/K, q = (A j + B K) j / K^2, whose integer part
// and fraction need no float at all; the same float operations as the CPU's
// follow, so for K a power of two (the default 8) the entries are the CPU's.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;

#include "table_builder_push_constants.h"
layout(push_constant) uniform Params { VRI_SECOND_ORDER_TABLE_PUSH_CONSTANTS } p;

#include "split_array.glsl"
SPLIT_OUTPUT(vec4, entries, 0, 4u)
// The first-order table of the chords (length L/K), N x N, [s_f][s_b].
layout(std430, binding = 4) readonly buffer Chords { vec4 e[]; } chords;

// floor(a / b) for b > 0.
int floor_div(int a, int b) {
  const int q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}

struct End {
  int i;    // the table index below the chord end, relative to f
  float w;  // the weight of index i + 1
};

End chord_end(int A, int B, int j) {
  const int K = p.iterations, KK = K * K;
  // q = P j / K^2 with P = A j + B K = u K + v, u j = c K + x:
  // q = c + (x K + v j) / K^2, 0 <= x K + v j < 2 K^2.
  const int P = A * j + B * K, u = floor_div(P, K), v = P - u * K;
  const int uj = u * j, c = floor_div(uj, K), x = uj - c * K;
  int r = x * K + v * j, i = c;
  if (r >= KK) r -= KK, i += 1;
  return End(i, float(r) / float(KK));
}

vec4 chord(int f, int b) {
  const int last = p.table_n - 1;
  return chords.e[clamp(f, 0, last) * p.table_n + clamp(b, 0, last)];
}

void main() {
  const int b = int(gl_GlobalInvocationID.x), m = int(gl_WorkGroupID.y), f = int(gl_WorkGroupID.z);
  if (b >= p.table_n) return;
  const int d1 = m - f, d2 = b - f, A = 2 * d2 - 4 * d1, B = 4 * d1 - d2;
  precise vec3 C = vec3(0.0);
  precise float T = 1.0;
  End front = chord_end(A, B, 0);
  for (int k = 0; k < p.iterations; ++k) {
    const End back = chord_end(A, B, k + 1);
    const int fi = front.i + f, bi = back.i + f;
    precise float c0 = (1.0 - front.w) * (1.0 - back.w);
    precise float c1 = front.w * (1.0 - back.w);
    precise float c2 = (1.0 - front.w) * back.w;
    precise float c3 = front.w * back.w;
    precise vec4 v = c0 * chord(fi, bi);
    v += c1 * chord(fi + 1, bi);
    v += c2 * chord(fi, bi + 1);
    v += c3 * chord(fi + 1, bi + 1);
    C += T * v.rgb;
    T *= 1.0 - v.a;
    front = back;
  }
  entries_put(uint((f * p.table_n + m) * p.table_n + b), vec4(C, 1.0 - T));
}
