#version 450
// tet-raycast on the GPU (SPEC §9), as TetRaycastIntegrator and TetWalk
// (src/methods/tet_raycast/tet_raycast.hpp, src/mesh/tet_walk.hpp)
// in float: the ray enters the medium through a boundary face found in the
// host's BoundaryBvh (Moller-Trumbore on the faces that face the ray, the
// nearest, ties to the lower face slot), leaves each tetrahedron through the
// face whose plane it crosses first, steps to the neighbour across it, and at
// the boundary looks for the next entry further on (non-convex meshes, holes;
// Garrity 1990, Weiler et al. 2003). Each piece - the field is linear in a
// tetrahedron - is looked up in the (l, s_f, s_b) table (Roettger & Ertl 2002,
// Sec. 3; slices of lengths max_length m / (M - 1), linear in l) and
// composited front to back. Lit (p.lit) with the point gradients
// interpolated in the tetrahedron (ChordLighting): 1 sampled, one normal from
// the mean of the gradients at entry and exit; 2 interpolated, the terms at
// both ends weighting Lum et al.'s front and back tables. Coordinates are
// the host's minus the mesh box's centre, so floats keep their bits where
// the mesh is.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;

#include "grid_params.glsl"
#include "tet_raycast_push_constants.h"
layout(push_constant) uniform Params { VRI_TET_RAYCAST_PUSH_CONSTANTS } p;

#include "split_array.glsl"
// Unlit and sampled: the table (slot 0); interpolated: the front and back weighted tables.
SPLIT_INPUT(vec4, table, 0, 4u, 0)
SPLIT_INPUT(vec4, weighted, 4, 4u, 1)
// Per tetrahedron 24 floats: four face planes (outward normal, offset), the
// linear field (gradient, offset, lo, hi), two unused.
layout(std430, binding = 8) readonly buffer Tets { float v[]; } tets;
layout(std430, binding = 9) readonly buffer Neighbors { int n[]; } neighbors;  // 4 per tetrahedron, -1: boundary
// The BVH over the boundary faces: nodes of 8 (lo, hi, first, count as int
// bits), faces of 10 (a, e1, e2, slot 4 tet + face as int bits).
layout(std430, binding = 10) readonly buffer Nodes { float v[]; } nodes;
layout(std430, binding = 11) readonly buffer Faces { float v[]; } faces;
// Lit, per tetrahedron 24 floats: vertex 0, the gradients of the barycentric
// coordinates of vertices 1, 2, 3, the point gradient at vertex 0 and those
// at 1, 2, 3 less it (PointGradients::sample).
layout(std430, binding = 12) readonly buffer Lighting { float v[]; } lighting;
// The camera block each ray is made from (camera_rays.glsl,
// src/methods/march/ray_setup.hpp), clipped to the mesh's widened box.
layout(std430, binding = 13) readonly buffer Rays { float r[]; } rays;
layout(std430, binding = 14) writeonly buffer Image { vec4 px[]; } image;

vec4 entry_of(int which, uint e) { return which == 0 ? table_at(e) : weighted_at(e); }

#include "exp_neg.glsl"
#include "table_lookup.glsl"
#include "shading.glsl"
#include "double_float.glsl"
#include "camera_rays.glsl"
const float kStop = 1e-7;  // the CPU's: T at most this ends the ray

vec3 o, d;
vec3 C = vec3(0.0);
float T = 1.0;

vec3 vec_at(uint base) { return vec3(tets.v[base], tets.v[base + 1u], tets.v[base + 2u]); }

// The linear field of `tet` at x, clamped to its vertex range.
float scalar_at(int tet, vec3 x) {
  const uint b = 24u * uint(tet) + 16u;
  return clamp(dot(vec_at(b), x) + tets.v[b + 3u], tets.v[b + 4u], tets.v[b + 5u]);
}

// Where the ray leaves `tet` (entered through entry_face, or -1): the nearest
// crossing of a face plane it goes out through, and that face.
float exit_of(int tet, int entry_face, out int face) {
  float best = 3.0e38, steepest = -3.0e38;
  int steepest_face = 0;
  face = -1;
  for (int f = 0; f < 4; ++f) {
    if (f == entry_face) continue;
    const uint b = 24u * uint(tet) + 4u * uint(f);
    const vec3 n = vec_at(b);
    const float dn = dot(n, d);
    if (dn > steepest) {
      steepest = dn;
      steepest_face = f;
    }
    if (!(dn > 0.0)) continue;
    const float t = (tets.v[b + 3u] - dot(n, o)) / dn;
    if (t < best) {
      best = t;
      face = f;
    }
  }
  if (face < 0) {  // not in a non-degenerate tetrahedron; a zero-length step, as the CPU
    face = steepest_face;
    return -3.0e38;
  }
  return best;
}

int face_towards(int tet, int other) {
  for (int f = 0; f < 4; ++f)
    if (neighbors.n[4 * tet + f] == other) return f;
  return -1;
}

// The nearest boundary face that faces the ray hit at t >= t_min and
// t > t_after, other than slot `skip` (BoundaryBvh::next_entry).
bool next_entry(float t_min, float t_after, int skip, out float hit_t, out int hit_slot) {
  hit_t = 3.0e38;
  hit_slot = -1;
  int stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const uint nb = 8u * uint(stack[--top]);
    float t0 = t_min, t1 = hit_t;
    bool miss = false;
    for (int a = 0; a < 3; ++a) {
      const float lo = nodes.v[nb + uint(a)], hi = nodes.v[nb + 3u + uint(a)];
      if (d[a] == 0.0) {
        if (o[a] < lo || o[a] > hi) miss = true;
        continue;
      }
      float ta = (lo - o[a]) / d[a], tb = (hi - o[a]) / d[a];
      if (ta > tb) {
        const float s = ta;
        ta = tb;
        tb = s;
      }
      t0 = max(t0, ta);
      t1 = min(t1, tb);
    }
    if (miss || t0 > t1 + 1e-6 * p.extent) continue;
    const int first = floatBitsToInt(nodes.v[nb + 6u]), count = floatBitsToInt(nodes.v[nb + 7u]);
    if (count == 0) {
      stack[top++] = first + 1;
      stack[top++] = first;
      continue;
    }
    for (int i = first; i < first + count; ++i) {
      const uint fb = 10u * uint(i);
      const int slot = floatBitsToInt(faces.v[fb + 9u]);
      if (slot == skip) continue;
      const vec3 a = vec3(faces.v[fb], faces.v[fb + 1u], faces.v[fb + 2u]);
      const vec3 e1 = vec3(faces.v[fb + 3u], faces.v[fb + 4u], faces.v[fb + 5u]);
      const vec3 e2 = vec3(faces.v[fb + 6u], faces.v[fb + 7u], faces.v[fb + 8u]);
      if (!(dot(cross(e1, e2), d) < 0.0)) continue;  // the ray enters through it
      const vec3 pv = cross(d, e2);
      const float det = dot(e1, pv);
      if (det == 0.0) continue;
      const vec3 tv = o - a;
      const float u = dot(tv, pv) / det;
      const float eps = 1e-5;  // closes the cracks between neighbouring faces (float)
      if (u < -eps || u > 1.0 + eps) continue;
      const vec3 qv = cross(tv, e1);
      const float v = dot(d, qv) / det;
      if (v < -eps || u + v > 1.0 + eps) continue;
      const float t = dot(e2, qv) / det;
      if (t < t_min || !(t > t_after)) continue;
      if (t < hit_t || (t == hit_t && slot < hit_slot)) {
        hit_t = t;
        hit_slot = slot;
      }
    }
  }
  return hit_slot >= 0;
}

// The table at length l and scalars (s_f, s_b): the two slices around l blended linearly.
vec4 lookup(int which, float l, float s_f, float s_b) {
  const Place at = length_place(l, p.max_length, p.lengths);
  const uint slice = uint(p.table_n * p.table_n);
  const Place f = place(s_f), b = place(s_b);
  return between(blend_at(which, uint(at.i) * slice, f, b), blend_at(which, uint(at.i + 1) * slice, f, b), at);
}

// The point gradients interpolated in `tet` at x (PointGradients::sample).
vec3 gradient_in(int tet, vec3 x) {
  const uint b = 24u * uint(tet);
  vec3 v[8];
  for (int k = 0; k < 8; ++k) v[k] = vec3(lighting.v[b + 3u * k], lighting.v[b + 3u * k + 1u], lighting.v[b + 3u * k + 2u]);
  const vec3 r = x - v[0];
  return v[4] + dot(v[1], r) * v[5] + dot(v[2], r) * v[6] + dot(v[3], r) * v[7];
}

// The piece of `tet` from t to t_out, scalars s and s_out, lit, composited.
void composite(int tet, float t, float t_out, float s, float s_out) {
  const float l = t_out - t;
  vec4 v;
  if (p.lit == 0) {
    v = lookup(0, l, s, s_out);
  } else {
    const vec3 front = o + t * d, back = o + t_out * d;
    if (p.lit == 1) {  // one normal, from the mean of the gradients at both ends
      const Terms m = terms_of(0.5 * (gradient_in(tet, front) + gradient_in(tet, back)), d);
      const vec4 e = lookup(0, l, s, s_out);
      v = vec4(e.rgb * m.a + m.b * e.a, e.a);
    } else {  // Lum et al.'s terms at both ends on the packed weighted tables (lit_weighted)
      const Terms f = terms_of(gradient_in(tet, front), d), k = terms_of(gradient_in(tet, back), d);
      const vec4 fw = lookup(0, l, s, s_out), bw = lookup(1, l, s, s_out);
      const float specular = f.b * (fw.a - bw.a) + k.b * bw.a;
      v = vec4(f.a * fw.rgb + k.a * bw.rgb + specular, fw.a);
    }
  }
  C += T * v.rgb;
  T *= 1.0 - v.a;
}

void main() {
  const uint pixel = PIXEL_INDEX();
  if (pixel >= p.pixels) return;
  // The origin less the mesh's centre, where the ray enters the box or at
  // the eye (t0 >= 0), world units: distances along it are the CPU's from there on.
  const PixelRay ray = pixel_ray(pixel);
  const DF to_world = df_div(DF(1.0, 0.0), cam_df(kCamScale));
  for (uint a = 0u; a < 3u; ++a)
    o[a] = df_float(df_mul(df_sub(df_add(ray.o[a], df_mul(ray.t0, ray.d[a])), cam_df(kCamOrigin + a)), to_world));
  d = float_direction(ray);
  // The clip (SPEC §12): the part of the ray kept, in the walk's distances
  // from the box entry; each piece is trimmed to it, as TetWalk trims.
  DF c0 = DF(0.0, 0.0), c1 = DF(3.0e38, 0.0);
  bool kept = true;
  clip_window(ray, c0, c1, kept);
  const float w0 = df_float(df_mul(df_sub(c0, ray.t0), to_world));
  const float w1 = c1.hi >= 3.0e38 ? 3.0e38 : df_float(df_mul(df_sub(c1, ray.t0), to_world));
  float t_exit = 0.0, t_entry = -1.0, hit_t;
  int skip = -1, slot;
  // Each entry is further than the one before, so this ends; a face
  // coincident with the one just left (a seam) may be hit a rounding before
  // the exit, hence the slack.
  while (ray.hits && kept && w1 > w0 && t_exit < w1 && T > kStop &&
         next_entry(t_exit - 1e-6 * (p.extent + abs(t_exit)), t_entry, skip, hit_t, slot)) {
    t_entry = hit_t;
    int tet = slot / 4, entry_face = slot % 4;
    float t = max(hit_t, t_exit);
    float s = scalar_at(tet, o + t * d);
    for (int steps = 0; steps < p.tets && T > kStop; ++steps) {
      int face;
      const float t_out = max(exit_of(tet, entry_face, face), t);
      const float s_out = scalar_at(tet, o + t_out * d);
      if (t >= w1) break;
      if (t_out > t && t_out > w0) {
        const float a = max(t, w0), b = min(t_out, w1);
        if (b > a)
          composite(tet, a, b, a == t ? s : scalar_at(tet, o + a * d), b == t_out ? s_out : scalar_at(tet, o + b * d));
      }
      t = t_out;
      const int next = neighbors.n[4 * tet + face];
      if (next < 0) {
        skip = 4 * tet + face;
        break;
      }
      entry_face = face_towards(next, tet);
      tet = next;
      s = scalar_at(tet, o + t * d);
    }
    t_exit = t;
  }
  image.px[pixel] = vec4(C, 1.0 - T);
}
