// The transfer function as the pre-integration tables see it, as DiscreteTf
// (src/tables/discrete_tf.hpp) holds it: its values at the N table
// scalars and, for a bin split at control points inside it, its linear
// sub-pieces; at_index(k, w) as DiscreteTf::at_index(k + w), in float. Three
// buffers from binding DISCRETE_TF_BINDING on (host/gpu_discrete_tf.hpp).
// Needs before it, in `p`: table_n.

struct SubPiece {
  // u0 and u1 from the start of their bin (continuous index units: a float
  // near 0 keeps more bits of them than one near the bin's index), u1 - u0, unused
  vec4 u;
  vec4 p, q;  // r, g, b, tau at u0 and at u1
};
// r, g, b, tau at each table scalar.
layout(std430, binding = DISCRETE_TF_BINDING) readonly buffer Samples { vec4 v[]; } samples;
// N + 1 of them: bin k's sub-pieces are [k[k], k[k + 1]).
layout(std430, binding = DISCRETE_TF_BINDING + 1) readonly buffer SubBegin { int k[]; } sub_begin;
layout(std430, binding = DISCRETE_TF_BINDING + 2) readonly buffer Subs { SubPiece s[]; } subs;

// (1 - w) a + w b, as DiscreteTf's lerp: exactly a at w = 0, b at w = 1.
vec4 tf_lerp(vec4 a, vec4 b, float w) {
  precise vec4 v = (1.0 - w) * a + w * b;
  return v;
}

// At continuous index k + w (k an integer, w in [0, 1)).
vec4 at_index(int k, float w) {
  const int i = min(k, p.table_n - 2);
  precise float u = w + float(k - i);  // from bin i's start
  const int first = sub_begin.k[i], end = sub_begin.k[i + 1];
  if (first == end) return tf_lerp(samples.v[i], samples.v[i + 1], u);
  // The first sub-piece that reaches u (the last one at u = 1).
  int j = first;
  while (j < end - 1 && !(subs.s[j].u.y > u)) ++j;
  const SubPiece s = subs.s[j];
  precise float t = s.u.z > 0.0 ? clamp((u - s.u.x) / s.u.z, 0.0, 1.0) : 1.0;
  return tf_lerp(s.p, s.q, t);
}
