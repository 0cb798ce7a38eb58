#version 450
// riemann on the GPU (SPEC §9; the CPU's float path, src/methods/riemann/float_riemann.hpp):
// one invocation per pixel sums the ray's samples front to back,
//   C += T (1 - exp(-tau_k h_k)) c_k,  T *= exp(-tau_k h_k)  (front_to_back.glsl),
// c_k lit (SPEC §5, shading.glsl: c a + b) when p.lit is 1,
// sample k at u0 + (k + o) du in grid units (o the jitter's fraction, 0
// without; the partial last step's own o and h_k), until the ray ends or T
// falls below the termination threshold. The host sets up each ray in double
// (clipping, sample count, the last step) exactly as the CPU does
// (src/methods/march/ray_setup.cpp), so only the per-sample float roundings differ.
// Samples in empty macro cells are leapt over (empty_space.glsl).
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;

#include "grid_params.glsl"
layout(push_constant) uniform Params {
  GRID_PARAMS
  float h;  // the step, world units
  float tf_lo, tf_scale;
  int tf_bins, segments;
  int lit;  // 0: unlit; 1: each sample lit
  float ka, kd, ks, shininess, flat_threshold;
  int skip;           // empty-space skipping: 1 on
  int macro_x, macro_y, macro_z;  // macro cells per axis (ints: an ivec3 would sit on 16 bytes)
} p;

#include "split_array.glsl"
SPLIT_INPUT(uint, volume, 0, 2u, 0)
SPLIT_INPUT(float, gradients, 4, 2u, 1)  // lit only
layout(std430, binding = 8) readonly buffer Tf { float v[]; } tf;
layout(std430, binding = 9) readonly buffer TfBins { int first[]; } bins;
// Per ray (ray_setup.hpp, kRiemannRayFloats): u0 (hi x3, lo x3), du (hi x3,
// lo x3), o (hi, lo), o of the last step (hi, lo), h_k of the last step,
// sample count, the direction (x, y, z).
layout(std430, binding = 10) readonly buffer Rays { float r[]; } rays;
layout(std430, binding = 11) readonly buffer EmptyCells { uint bits[]; } empty_cells;
layout(std430, binding = 12) writeonly buffer Image { vec4 px[]; } image;

#include "double_float.glsl"
#include "front_to_back.glsl"
#include "exp_neg.glsl"
#include "grid_sampler.glsl"
#include "transfer_function.glsl"
#include "shading.glsl"

DF u0[3], du[3];
#include "empty_space.glsl"

const uint kRayFloats = 21u;

void main() {
  const uint pixel = PIXEL_INDEX();
  if (pixel >= p.pixels) return;
  const uint b = pixel * kRayFloats;
  const int n = floatBitsToInt(rays.r[b + 17u]);
  for (int a = 0; a < 3; ++a) {
    u0[a] = DF(rays.r[b + a], rays.r[b + 3 + a]);
    du[a] = DF(rays.r[b + 6 + a], rays.r[b + 9 + a]);
  }
  const DF o = DF(rays.r[b + 12u], rays.r[b + 13u]), o_last = DF(rays.r[b + 14u], rays.r[b + 15u]);
  const float h_last = rays.r[b + 16u];
  const vec3 d = vec3(rays.r[b + 18u], rays.r[b + 19u], rays.r[b + 20u]);
  FrontToBack acc = ftb_start();
  for (int k = 0; k < n; ++k) {
    if (ftb_below(acc, GRID_TERMINATION)) break;
    const bool last = k == n - 1;
    const DF t = df_two_sum(float(k), last ? o_last.hi : o.hi);
    const DF at_k = df_add(t, DF(0.0, last ? o_last.lo : o.lo));
    DF u[3];
    for (int a = 0; a < 3; ++a) u[a] = df_add(u0[a], df_mul(at_k, du[a]));
    const Cell cell = grid_cell(u);
    if (!last && macro_empty(cell)) {
      // Samples k .. j lie in this empty macro cell; the next to look at is j + 1.
      const int j = int(floor(macro_exit(cell) - o.hi));
      k = max(k, min(j + 1, n - 1) - 1);
      continue;
    }
    vec4 v = tf_at(interpolate(cell));
    if (p.lit != 0) {
      if (v.w == 0.0) continue;  // adds exactly nothing: no gradient needed
      const Terms t = terms_of(gradient_at(cell), d);
      precise vec3 c = v.rgb * t.a + t.b;
      v.rgb = c;
    }
    const float h_k = last ? h_last : p.h;
    ftb_add_step(acc, v.rgb, exp_neg(v.w * h_k));
  }
  image.px[pixel] = ftb_pixel(acc);
}
