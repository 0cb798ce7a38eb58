#version 450
// adaptive, strategy guaranteed (SPEC §9), on the GPU: the per-ray walk of
// GuaranteedAdaptiveIntegrator (src/methods/adaptive/adaptive_guaranteed.hpp,
// vri's extension of Campagnolo, Celes & de Figueiredo 2015) in one
// invocation, in float:
//  - the ray is cut at cell faces (cell_walk.glsl) and, inside a cell, where
//    the trilinear signal - a cubic in t (cubic.glsl) - crosses a transfer
//    function breakpoint (tf_pieces.hpp: the cubic's monotone pieces, each
//    breakpoint between their end values found by a bracketed Newton), lit
//    also where N.d changes sign; every piece lies on one linear segment of
//    the transfer function and pieces on transparent segments take no
//    samples;
//  - each piece is integrated by Simpson steps with the paper's step
//    control (Algorithm 2), from the whole piece, at most hmax and the cap of
//    step_cap (optical depth 0.5, colour change 0.25 a step), no hmin; a
//    step is accepted when the colour error <= 0.45 tol h / L and the
//    optical depth's times T <= that over the brightest lit colour (L: the
//    ray's length in the volume); the ray stops at T < 0.1 tol / brightest;
//  - the walk leaps over the rest of an empty macro cell, and a cell whose
//    corners' range (with the macro cells' margin) holds only transparent
//    segments is passed over.
// The error estimates carry float roundings, so a step the CPU accepts the
// GPU may halve or the reverse; each image meets the tolerance against
// `exact` (docs/GPU.md).
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;

#include "grid_params.glsl"
#include "adaptive_push_constants.h"
layout(push_constant) uniform Params { VRI_ADAPTIVE_GUARANTEED_PUSH_CONSTANTS } p;

#include "split_array.glsl"
SPLIT_INPUT(uint, volume, 0, 2u, 0)
SPLIT_INPUT(float, gradients, 4, 2u, 1)  // lit only
layout(std430, binding = 8) readonly buffer Tf { float v[]; } tf;
layout(std430, binding = 9) readonly buffer TfBins { int first[]; } bins;
// opaque.before[i]: segments 0 .. i-1 with tau not zero (i = 0 .. segments).
layout(std430, binding = 10) readonly buffer Opaque { int before[]; } opaque;
// The camera block each ray is made from (camera_rays.glsl,
// src/methods/march/ray_setup.hpp).
layout(std430, binding = 11) readonly buffer Rays { float r[]; } rays;
layout(std430, binding = 12) readonly buffer EmptyCells { uint bits[]; } empty_cells;
layout(std430, binding = 13) writeonly buffer Image { vec4 px[]; } image;

#include "double_float.glsl"
#include "exp_neg.glsl"
#include "grid_sampler.glsl"
#include "transfer_function.glsl"
#include "shading.glsl"
#include "cubic.glsl"
#include "simpson_step.glsl"

#include "camera_rays.glsl"

DF u0[3], du[3];
vec3 d;
#include "empty_space.glsl"
#include "cell_walk.glsl"

// Segment i of the transfer function (transfer_function.glsl's layout).
bool transparent(int i) { return opaque.before[i + 1] == opaque.before[i]; }
float breakpoint(int i) { return tf.v[i]; }
vec4 segment_at(int i, float s) {
  const int n = p.segments;
  const float ds = s - tf.v[n + i];
  vec4 v;
  for (int c = 0; c < 4; ++c) v[c] = tf.v[(2 + c) * n + i] + tf.v[(6 + c) * n + i] * ds;
  return v;
}
vec4 segment_slope(int i) {
  const int n = p.segments;
  return vec4(tf.v[6 * n + i], tf.v[7 * n + i], tf.v[8 * n + i], tf.v[9 * n + i]);
}

// The march's state: the pixel so far, the budgets, the current cell's cubics.
vec3 C = vec3(0.0);
float T = 1.0;
float colour_density, depth_density, cutoff;
vec4 signal;   // the scalar along the cell, t from its entry
vec4 grad[3];  // lit: the gradient along the cell
float kinks[3];
int nkinks = 0;

// What a piece can change over a step bounds the step (adaptive_guaranteed.cpp,
// step_cap): optical depth 0.5 and colour change 0.25 a step at most.
float step_cap(int seg, float x, float y) {
  const vec4 slope = segment_slope(seg);
  // tau is linear on the segment: largest at an end (the end segments, open
  // towards +-inf, are constant).
  float tau_max = tf.v[5 * p.segments + seg];
  if (slope.w != 0.0 && seg > 0 && seg + 1 < p.segments)
    tau_max = max(segment_at(seg, breakpoint(seg - 1)).w, segment_at(seg, breakpoint(seg)).w);
  const float dc_ds = max(max(abs(slope.x), abs(slope.y)), abs(slope.z));
  float ds_dt = max(abs(cubic_slope(signal, x)), abs(cubic_slope(signal, y)));
  if (signal.w != 0.0) {
    const float v = -signal.z / (3.0 * signal.w);
    if (v > x && v < y) ds_dt = max(ds_dt, abs(cubic_slope(signal, v)));
  }
  float cap = 3.0e38;
  if (tau_max > 0.0) cap = 0.5 / tau_max;
  if (dc_ds * ds_dt > 0.0) cap = min(cap, 0.25 / (dc_ds * ds_dt));
  return cap;
}

// (r, g, b, tau) at t of the cell, on segment seg, lit.
vec4 sample_at(int seg, float t) {
  vec4 v = segment_at(seg, cubic_at(signal, t));
  if (p.lit != 0) {
    const Terms l = terms_of(vec3(cubic_at(grad[0], t), cubic_at(grad[1], t), cubic_at(grad[2], t)), d);
    v.rgb = v.rgb * l.a + l.b;
  }
  return v;
}

// One smooth piece [x, y] of the cell on segment seg (integrate_piece).
void integrate_piece(int seg, float x, float y) {
  vec4 f[5];
  float at[5];
  bool known[5] = bool[5](false, false, false, false, false);
  const float hcap = max(p.hfloor, min(p.hmax, step_cap(seg, x, y)));
  float h_next = min(y - x, hcap);
  bool last_succeeded = true;
  for (float u = x; u < y && T > cutoff;) {
    const float h = min(h_next, y - u);
    for (int k = 0; k < 5; ++k) {
      const float t = u + h * (0.25 * float(k));
      if (known[k] && at[k] == t) continue;
      f[k] = sample_at(seg, t);
      at[k] = t;
      known[k] = true;
    }
    const ColourStep st = colour_step(f, T, h);
    const float depth_err = T * tau_error(f, h);
    const bool ok = (colour_error(st) <= colour_density * h && depth_err <= depth_density * h) || h <= p.hfloor;
    if (!ok) {  // halve: 0, 1/4 and 1/2 of this try are 0, 1/2 and 1 of the next
      f[4] = f[2], at[4] = at[2];
      f[2] = f[1], at[2] = at[1];
      known[1] = known[3] = false;
      h_next = max(0.5 * h, p.hfloor);
      last_succeeded = false;
      continue;
    }
    T = add_step(st, T, C);
    if (last_succeeded) h_next = min(2.0 * h_next, hcap);
    last_succeeded = true;
    f[0] = f[4], at[0] = at[4];
    known[1] = known[2] = known[3] = known[4] = false;
    u = h >= y - u ? y : u + h;
  }
}

// A piece [x, y] on segment seg, cut at the kinks of |N.d| inside it.
void piece(int seg, float x, float y) {
  for (int k = 0; k < nkinks; ++k)
    if (kinks[k] > x && kinks[k] < y) {
      integrate_piece(seg, x, kinks[k]);
      x = kinks[k];
    }
  integrate_piece(seg, x, y);
}

// [x, y] on the segment that holds its middle, unless transparent.
void emit(float x, float y) {
  if (!(y > x)) return;
  const int seg = tf_segment(cubic_at(signal, 0.5 * (x + y)));
  if (!transparent(seg)) piece(seg, x, y);
}

// The cell's [0, len] cut where the signal crosses breakpoints (TfPieceSplitter::split).
void split(float len) {
  float knots[4], vals[4], crit[2];
  const int nc = critical_points(signal, len, crit);
  const int nk = nc + 2;
  knots[0] = 0.0;
  for (int i = 0; i < nc; ++i) knots[1 + i] = crit[i];
  knots[nk - 1] = len;
  float smin = 3.0e38, smax = -3.0e38;
  for (int i = 0; i < nk; ++i) {
    vals[i] = cubic_at(signal, knots[i]);
    smin = min(smin, vals[i]);
    smax = max(smax, vals[i]);
  }
  const int i0 = tf_segment(smin), i1 = tf_segment(smax);
  if (opaque.before[i1 + 1] == opaque.before[i0]) return;
  if (i0 == i1) {  // one segment holds every value: the monotone pieces
    for (int m = 0; m + 1 < nk; ++m)
      if (knots[m + 1] > knots[m]) piece(i0, knots[m], knots[m + 1]);
    return;
  }
  for (int m = 0; m + 1 < nk; ++m) {
    const float ka = knots[m], kb = knots[m + 1], fa = vals[m], fb = vals[m + 1];
    float prev = ka;
    if (fa < fb) {  // the breakpoints in (fa, fb), ascending
      for (int j = tf_segment(fa); breakpoint(j) < fb; ++j) {
        const float r = clamp(solve_monotone(signal, breakpoint(j), ka, kb), prev, kb);
        emit(prev, r);
        prev = r;
      }
    } else if (fa > fb) {  // those in (fb, fa], descending
      int j = tf_segment(fa);
      while (j > 0 && breakpoint(j - 1) >= fa) --j;
      while (j > 0 && breakpoint(j - 1) > fb) {
        --j;
        const float r = clamp(solve_monotone(signal, breakpoint(j), ka, kb), prev, kb);
        emit(prev, r);
        prev = r;
      }
    }
    emit(prev, kb);
  }
}

void main() {
  const uint pixel = PIXEL_INDEX();
  if (pixel >= p.pixels) return;
  // The ray from its entry into the box: u0 + t du, t in world units up to t_end (< 0: a miss).
  const PixelRay ray = pixel_ray(pixel);
  grid_entry(ray, cam_df(kCamScale), u0, du);  // finite on a miss too
  const DF t_end = ray.hits ? world_length(ray) : DF(-1.0, 0.0);
  d = float_direction(ray);
  // The budgets (adaptive_guaranteed.cpp): the ray's share of the tolerance
  // per unit length; lit colours reach ka + kd + ks.
  const float brightest = p.lit != 0 ? max(1.0, p.ka + p.kd + p.ks) : 1.0;
  colour_density = 0.45 * p.tolerance / df_float(t_end);
  depth_density = colour_density / brightest;
  cutoff = 0.1 * p.tolerance / brightest;
  const vec3 dir = vec3(df_float(du[0]), df_float(du[1]), df_float(du[2]));
  CellWalk w = walk_start();
  while (t_end.hi > 0.0 && df_less(w.ta, t_end) && T > cutoff) {
    const DF ta = w.ta, tb = walk_next(w, t_end);
    w.ta = tb;
    if (!df_less(ta, tb)) continue;
    Cell cell;
    cell.index = piece_cell(ta, tb);
    if (macro_empty(cell)) {
      walk_leap(w, cell.index, t_end);
      continue;
    }
    const uint o = uint(cell.index.x) + p.sy * uint(cell.index.y) + p.sz * uint(cell.index.z);
    const uint offsets[8] = uint[8](0u, 1u, p.sy, p.sy + 1u, p.sz, p.sz + 1u, p.sz + p.sy, p.sz + p.sy + 1u);
    float v[8];
    float lo = 3.0e38, hi = -3.0e38;
    for (int k = 0; k < 8; ++k) {
      v[k] = voxel(o + offsets[k]);
      lo = min(lo, v[k]);
      hi = max(hi, v[k]);
    }
    if (opaque.before[tf_segment(hi + p.margin) + 1] == opaque.before[tf_segment(lo - p.margin)]) continue;
    const vec3 x0 = local_in(cell.index, ta);
    const float len = df_float(df_sub(tb, ta));
    signal = trilinear_along(v, x0, dir);
    nkinks = 0;
    if (p.lit != 0) {
      for (int a = 0; a < 3; ++a) {
        float gv[8];
        for (int k = 0; k < 8; ++k) gv[k] = gradients_at(3u * (o + offsets[k]) + uint(a));
        grad[a] = trilinear_along(gv, x0, dir);
      }
      nkinks = sign_changes(grad[0] * d.x + grad[1] * d.y + grad[2] * d.z, len, kinks);
    }
    split(len);
  }
  image.px[pixel] = vec4(C, 1.0 - T);
}
