#version 450
// Lum, Wilson & Ma 2004's incremental subrange integration (§4.2, Figs. 4-5)
// on the GPU, as IncrementalBuilder (src/tables/incremental_builder.hpp,
// src/tables/incremental_diagonals.cpp) computes it on the CPU, in float.
// Entry (i, i+m) composites the m pieces between table scalars i and i+m,
// each of length l/m; along diagonal m the pieces fall into bins of m, in
// each of which the left-hand subranges grow to the right and the
// right-hand ones to the left - a prefix computation - and every entry
// joins one right-hand subrange of a bin with one left-hand subrange of the
// next (one "over"). Three passes, all diagonals at once:
//   PHASE 1: per (piece k, diagonal m) its forward and backward (C, alpha)
//            (piece_weights.glsl; a bin split at control points inside it
//            composited from its sub-pieces, exactly as on the CPU);
//   PHASE 2: per (bin, diagonal m) the four chains over its pieces: heads
//            forward and backward, tails forward and backward;
//   PHASE 3: per entry (i, i+m) and (i+m, i) the join; the diagonal m = 0
//            the homogeneous slab.
// Scratch: six arrays of (N-1)^2 (C, alpha), index (m - 1)(N - 1) + k.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;

#include "table_builder_push_constants.h"
layout(push_constant) uniform Params { VRI_INCREMENTAL_TABLE_PUSH_CONSTANTS } p;

#include "split_array.glsl"
SPLIT_OUTPUT(vec4, entries, 0, 4u)
#define DISCRETE_TF_BINDING 4
#include "discrete_tf.glsl"
layout(std430, binding = 7) buffer PieceF { vec4 v[]; } piece_f;
layout(std430, binding = 8) buffer PieceB { vec4 v[]; } piece_b;
layout(std430, binding = 9) buffer HeadF { vec4 v[]; } head_f;
layout(std430, binding = 10) buffer HeadB { vec4 v[]; } head_b;
layout(std430, binding = 11) buffer TailF { vec4 v[]; } tail_f;
layout(std430, binding = 12) buffer TailB { vec4 v[]; } tail_b;
#include "exp_neg.glsl"
#include "piece_weights.glsl"

void main() {
  const int n = p.table_n, pieces = n - 1;
  const int x = int(gl_GlobalInvocationID.x), m = int(gl_WorkGroupID.y) + 1 - (PHASE == 3 ? 1 : 0);
#if PHASE == 1
  const int k = x;  // piece k: table scalars k, k + 1
  if (k >= pieces) return;
  const float d = p.slab_length / float(m);  // a piece's length
  const uint at = uint((m - 1) * pieces + k);
  const int first = sub_begin.k[k], end = sub_begin.k[k + 1];
  if (first == end) {
    vec4 f, b;
    linear_piece(samples.v[k], samples.v[k + 1], d, f, b);
    piece_f.v[at] = f;
    piece_b.v[at] = b;
    return;
  }
  // A split bin: its sub-pieces composited both ways, alpha from their depth.
  vec4 f = vec4(0.0), b = vec4(0.0);
  float depth = 0.0;
  for (int j = first; j < end; ++j) {
    const SubPiece s = subs.s[j];
    vec4 forward, backward;
    linear_piece(s.p, s.q, s.u.z * d, forward, backward);
    f = over(f, forward);
    depth += 0.5 * (s.p.w + s.q.w) * s.u.z;
  }
  for (int j = end - 1; j >= first; --j) {
    const SubPiece s = subs.s[j];
    vec4 forward, backward;
    linear_piece(s.q, s.p, s.u.z * d, forward, backward);
    b = over(b, forward);
  }
  const float alpha = one_minus_exp_neg(depth * d);
  piece_f.v[at] = vec4(f.rgb, alpha);
  piece_b.v[at] = vec4(b.rgb, alpha);
#elif PHASE == 2
  const int start = x * m;  // bin x: pieces start .. end - 1
  if (start >= pieces) return;
  const int end = min(start + m, pieces), base = (m - 1) * pieces;
  vec4 hf = piece_f.v[base + start], hb = piece_b.v[base + start];
  vec4 tf = piece_f.v[base + end - 1], tb = piece_b.v[base + end - 1];
  float hf_t = 1.0 - hf.a, tb_t = 1.0 - tb.a;
  head_f.v[base + start] = hf;
  head_b.v[base + start] = hb;
  tail_f.v[base + end - 1] = tf;
  tail_b.v[base + end - 1] = tb;
  for (int h = start + 1, t = end - 2; h < end; ++h, --t) {
    const vec4 ph = piece_f.v[base + h], pbh = piece_b.v[base + h];
    const vec4 pt = piece_f.v[base + t], pbt = piece_b.v[base + t];
    hf += hf_t * ph;          // head_f[h] = over(head_f[h-1], piece)
    hf_t *= 1.0 - ph.a;
    hb = pbh + (1.0 - pbh.a) * hb;  // head_b[h] = over(piece, head_b[h-1])
    tf = pt + (1.0 - pt.a) * tf;    // tail_f[t] = over(piece, tail_f[t+1])
    tb += tb_t * pbt;         // tail_b[t] = over(tail_b[t+1], piece)
    tb_t *= 1.0 - pbt.a;
    head_f.v[base + h] = hf;
    head_b.v[base + h] = hb;
    tail_f.v[base + t] = tf;
    tail_b.v[base + t] = tb;
  }
#else
  const int i = x;
  if (i + m >= n) return;
  if (m == 0) {  // the homogeneous slab: alpha = 1 - exp(-tau l), C = c alpha
    const vec4 v = samples.v[i];
    const float a = one_minus_exp_neg(v.w * p.slab_length);
    entries_put(uint(i * n + i), vec4(v.rgb * a, a));
    return;
  }
  const int e = i + m - 1, base = (m - 1) * pieces;
  vec4 upper = tail_f.v[base + i], lower = tail_b.v[base + i];
  if (i % m != 0) {
    upper = over(upper, head_f.v[base + e]);
    lower = over(head_b.v[base + e], lower);
  }
  entries_put(uint(i * n + i + m), upper);
  entries_put(uint((i + m) * n + i), lower);
#endif
}
