#version 450
// riemann on the GPU (SPEC §9; the CPU's float path, src/methods/riemann/float_riemann.hpp):
// one invocation per pixel sums the ray's samples front to back,
//   C += T (1 - exp(-tau_k h_k)) c_k,  T *= exp(-tau_k h_k)  (front_to_back.glsl),
// c_k lit (SPEC §5, shading.glsl: c a + b) when p.lit is 1,
// sample k at u0 + (k + o) du in grid units (o the jitter's fraction, 0
// without; the partial last step's own o and h_k), until the ray ends or T
// falls below the termination threshold. Each ray is made here from the
// camera in double-float (camera_rays.glsl: clipping, sample count, the last
// step as the CPU's double), so only the per-sample float roundings differ.
// Samples in empty macro cells are leapt over (empty_space.glsl).
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;

#include "grid_params.glsl"
#include "riemann_push_constants.h"
layout(push_constant) uniform Params { VRI_RIEMANN_PUSH_CONSTANTS } p;

#include "split_array.glsl"
SPLIT_INPUT(uint, volume, 0, 2u, 0)
SPLIT_INPUT(float, gradients, 4, 2u, 1)  // lit only
layout(std430, binding = 8) readonly buffer Tf { float v[]; } tf;
layout(std430, binding = 9) readonly buffer TfBins { int first[]; } bins;
// The camera block (src/methods/march/ray_setup.hpp), then with jitter each
// pixel's fraction o (hi, lo).
layout(std430, binding = 10) readonly buffer Rays { float r[]; } rays;
layout(std430, binding = 11) readonly buffer EmptyCells { uint bits[]; } empty_cells;
layout(std430, binding = 12) writeonly buffer Image { vec4 px[]; } image;

#include "double_float.glsl"
#include "front_to_back.glsl"
#include "exp_neg.glsl"
#include "grid_sampler.glsl"
#include "transfer_function.glsl"
#include "shading.glsl"
#include "camera_rays.glsl"

DF u0[3], du[3];
#include "empty_space.glsl"

// min(h, t1 - (t0 + (n - 1) h)): the length of step n - 1, frame units.
DF step_length(PixelRay ray, DF h, int n) {
  return df_min(h, df_sub(ray.t1, df_add(ray.t0, df_mul(df_from_int(n - 1), h))));
}

void main() {
  const uint pixel = PIXEL_INDEX();
  if (pixel >= p.pixels) return;
  const PixelRay ray = pixel_ray(pixel);
  const DF h = cam_df(kCamStep);
  int n = 0;
  DF o = DF(0.0, 0.0), o_last = o;
  float h_last = 0.0;
  if (ray.hits) {
    // As float_riemann.hpp: n = max(1, ceil(length / h)); the CPU stops at
    // the first step with h_k <= 0 (a ray that only grazes the box).
    n = max(1, -df_floor_int(df_neg(df_div(df_sub(ray.t1, ray.t0), h))));
    DF h_n = step_length(ray, h, n);
    if (!(h_n.hi > 0.0)) {
      --n;
      h_n = n > 0 ? step_length(ray, h, n) : DF(0.0, 0.0);
    }
    if (cam_uint(kCamExtras) != 0u) o = DF(pixel_extra(pixel, 0u), pixel_extra(pixel, 1u));
    o_last = df_less(h_n, h) ? df_div(df_mul(o, h_n), h) : o;
    h_last = df_float(df_div(h_n, cam_df(kCamScale)));
    grid_entry(ray, h, u0, du);
  }
  const vec3 d = float_direction(ray);
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
