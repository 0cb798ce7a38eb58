#version 450
// preint1 (STEPS 1) and preint2 (STEPS 2) on the GPU, as the CPU's float
// path (src/methods/preint/float_march.hpp): samples at u0 + i du; each slab of
// STEPS steps is one lookup of the pre-integration table, composited front
// to back, C += T c, T *= 1 - alpha (in double-float, front_to_back.glsl).
//   STEPS 1 (SPEC §9 preint1; Engel, Kraus & Ertl 2001): the slab between
//     two samples, the table at (s_f, s_b).
//   STEPS 2 (SPEC §9 preint2; El Hajjar et al. 2008, eqs. 2-3): the slab
//     over three samples, the second-order table at (s_f, s_m, s_b).
// Lit (SPEC §5, p.lit): `sampled` lights the slab's colour with the mean of
// its samples' gradients; `interpolated` weights the terms at its samples
// with the weighted tables (Lum, Wilson & Ma 2004: front and back for
// preint1; full, middle and back for preint2, lit_slab.hpp). The last,
// partial slab (shorter than STEPS steps) is integrated exactly on the host
// as STEPS sub-slabs, as on the CPU (last_slabs): this writes, for each
// pixel, where it stopped (the whole slabs, or -1: no partial slab to add)
// and T, and the host composites the rest (vulkan_preint.cpp). Each ray is
// made here from the camera (camera_rays.glsl). Slabs inside empty macro
// cells are leapt over (empty_space.glsl).
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;

#include "grid_params.glsl"
#include "preint_push_constants.h"
layout(push_constant) uniform Params { VRI_PREINT_PUSH_CONSTANTS } p;

#include "split_array.glsl"
SPLIT_INPUT(uint, volume, 0, 2u, 0)
// Unlit and sampled: the table. Interpolated: the weighted tables, front to
// back (preint1: front, back; preint2: full, middle, back).
SPLIT_INPUT(vec4, table, 4, 4u, 1)
SPLIT_INPUT(vec4, weighted1, 8, 4u, 2)
SPLIT_INPUT(vec4, weighted2, 12, 4u, 3)
SPLIT_INPUT(float, gradients, 16, 2u, 4)  // lit only
// The camera block (src/methods/march/ray_setup.hpp).
layout(std430, binding = 20) readonly buffer Rays { float r[]; } rays;
layout(std430, binding = 21) readonly buffer EmptyCells { uint bits[]; } empty_cells;
layout(std430, binding = 22) writeonly buffer Image { vec4 px[]; } image;
// Per pixel, 9 floats: the whole slabs composited (int bits; -1: add no
// partial slab), then T, r, g, b so far, each hi and lo (the host goes on in double).
layout(std430, binding = 23) writeonly buffer Tails { float v[]; } tails;

vec4 entry_of(int which, uint e) { return which == 0 ? table_at(e) : which == 1 ? weighted1_at(e) : weighted2_at(e); }

#include "double_float.glsl"
#include "front_to_back.glsl"
#include "exp_neg.glsl"
#include "grid_sampler.glsl"
#include "table_lookup.glsl"
#include "shading.glsl"
#include "camera_rays.glsl"

DF u0[3], du[3];
vec3 d;
#include "empty_space.glsl"

struct Sample {
  float exit;  // in an empty macro cell: the parameter just short of its exit (macro_exit); else -1
  Place place;
  vec3 g;   // lit: the gradient
  Terms t;  // interpolated: the terms
};

// `front`: the sample may start a slab (its leap is found).
Sample sample_at(int i, bool front) {
  DF u[3];
  const DF k = DF(float(i), 0.0);
  for (int a = 0; a < 3; ++a) u[a] = df_add(u0[a], df_mul(k, du[a]));
  const Cell cell = grid_cell(u);
  Sample out_s;
  out_s.exit = front && macro_empty(cell) ? macro_exit(cell) : -1.0;
  out_s.place = place(interpolate(cell));
  out_s.g = vec3(0.0);
  out_s.t = Terms(0.0, 0.0);
  if (p.lit != 0) out_s.g = gradient_at(cell);
  if (p.lit == 2) out_s.t = terms_of(out_s.g, d);
  return out_s;
}

vec4 lit_by(Terms t, vec4 v) {
  precise vec3 c = v.rgb * t.a + t.b * v.a;
  return vec4(c, v.a);
}

// The slab over samples s[0 .. STEPS], lit as p.lit says (float_march.hpp,
// slab_colour; lit_slab.hpp).
#if STEPS == 1
vec4 slab(Sample f, Sample b) {
  if (p.lit == 0) return blend(0, f.place, b.place);
  if (p.lit == 1) {
    precise vec3 sum = f.g + b.g;
    precise vec3 g = sum * 0.5;
    return lit_by(terms_of(g, d), blend(0, f.place, b.place));
  }
  const vec4 fw = blend(0, f.place, b.place), bw = blend(1, f.place, b.place);
  precise float specular = f.t.b * (fw.a - bw.a) + b.t.b * bw.a;
  precise vec3 c = f.t.a * fw.rgb + b.t.a * bw.rgb + specular;
  return vec4(c, fw.a);
}
#else
vec4 slab(Sample f, Sample m, Sample b) {
  if (p.lit == 0) return blend(0, f.place, m.place, b.place);
  if (p.lit == 1) {
    precise vec3 sum = (f.g + m.g) + b.g;
    precise vec3 g = sum * uintBitsToFloat(0x3eaaaaabu);  // 1.0f / 3, as the CPU's mean
    return lit_by(terms_of(g, d), blend(0, f.place, m.place, b.place));
  }
  const vec4 full = blend(0, f.place, m.place, b.place), middle = blend(1, f.place, m.place, b.place);
  const vec4 back = blend(2, f.place, m.place, b.place);
  precise float s_f = (full.a - middle.a) - back.a;
  precise float specular = (f.t.b * s_f + m.t.b * middle.a) + b.t.b * back.a;
  precise vec3 d_f = (full.rgb - middle.rgb) - back.rgb;
  precise vec3 c = ((f.t.a * d_f + m.t.a * middle.rgb) + b.t.a * back.rgb) + specular;
  return vec4(c, full.a);
}
#endif

void main() {
  const uint pixel = PIXEL_INDEX();
  if (pixel >= p.pixels) return;
  const PixelRay ray = pixel_ray(pixel);
  const DF h = cam_df(kCamStep);
  // As float_march.hpp: the whole slabs, floor(length / (STEPS h)); -1: a miss.
  const int full = ray.hits ? df_floor_int(df_div(df_sub(ray.t1, ray.t0), df_mul_f(h, float(STEPS)))) : -1;
  grid_entry(ray, h, u0, du);  // finite on a miss too
  d = float_direction(ray);
  FrontToBack acc = ftb_start();
  if (full >= 0) {  // -1: the ray misses the volume
    // Each turn takes the samples of one slab after `front` and composites
    // it - or, where the front lies in an empty macro cell, leaps: the slabs
    // with all their samples in it (up to floor(exit)) read only zero
    // entries, and the turn takes the samples of the slab that ends at the
    // new front instead, without compositing. So every ray samples at the
    // same places in the code in every turn (SIMD lanes stay together).
    Sample front = sample_at(0, true);
    for (int k = 0; k < full;) {  // `front` is slab k's
      if (ftb_below(acc, GRID_TERMINATION)) break;
      int to = k + 1;
      bool composite = true;
      if (front.exit >= 0.0) {
        const int next = int(floor(front.exit)) / STEPS;
        if (next >= full) break;
        if (next > k) to = next, composite = false;
      }
#if STEPS == 1
      const Sample back = sample_at(to, true);
      const vec4 v = composite ? slab(front, back) : vec4(0.0);
#else
      const Sample middle = sample_at(2 * to - 1, false), back = sample_at(2 * to, true);
      const vec4 v = composite ? slab(front, middle, back) : vec4(0.0);
#endif
      ftb_add(acc, v);
      front = back;
      k = to;
    }
  }
  // The host adds the partial slab unless the ray missed or stopped early.
  const bool tail = full >= 0 && !ftb_below(acc, GRID_TERMINATION);
  const uint at = 9u * pixel;
  tails.v[at] = intBitsToFloat(tail ? full : -1);
  const DF sums[4] = DF[4](acc.T, acc.r, acc.g, acc.b);
  for (uint k = 0u; k < 4u; ++k) {
    tails.v[at + 1u + 2u * k] = sums[k].hi;
    tails.v[at + 2u + 2u * k] = sums[k].lo;
  }
  image.px[pixel] = ftb_pixel(acc);
}
