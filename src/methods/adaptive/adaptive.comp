#version 450
// adaptive, strategies coupled and decoupled (SPEC §9; Campagnolo, Celes &
// de Figueiredo 2015, Algorithms 2 and 3), on the GPU: the per-ray loop of
// AdaptiveSimpsonIntegrator (src/methods/adaptive/adaptive_simpson.hpp)
// in one invocation, in float. A step [t, t+h] is tried with Simpson's rule
// S(t,h), D(t,h) = S(t,h/2) + S(t+h/2,h/2), E = |D - S|/15 (simpson5.hpp);
// E > eps halves the step and eps, a second consecutive success doubles
// both, h in [hmin, hmax], eps = tol at h0. The inner integral (optical
// depth) finds a step from t; the outer one (r, g, b, alpha) integrates
// over it - `coupled` starting from the inner step, `decoupled` at its own
// pace - with the optical depth inside each try from the quartic through
// the tau samples; an inner interval with all five samples transparent
// skips the outer one. Evaluations shared by adjacent steps and halves are
// reused (a cache of the last 12, by their exact t). Samples: the scalar by
// trilinear interpolation (grid_sampler.glsl), the transfer function
// (transfer_function.glsl), lit with c a + b (shading.glsl). Positions
// u0 + t du in double-float; t measured from the ray's entry.
// With skipping on, as the CPU: only the runs of non-empty macro cells are
// integrated (occupied_runs.glsl), each from h0, T carried, and the ray
// stops at T < 0.1 tol / brightest.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;

#include "grid_params.glsl"
#include "adaptive_push_constants.h"
layout(push_constant) uniform Params { VRI_ADAPTIVE_PUSH_CONSTANTS } p;

#include "split_array.glsl"
SPLIT_INPUT(uint, volume, 0, 2u, 0)
SPLIT_INPUT(float, gradients, 4, 2u, 1)  // lit only
layout(std430, binding = 8) readonly buffer Tf { float v[]; } tf;
layout(std430, binding = 9) readonly buffer TfBins { int first[]; } bins;
// The camera block each ray is made from (camera_rays.glsl,
// src/methods/march/ray_setup.hpp).
layout(std430, binding = 10) readonly buffer Rays { float r[]; } rays;
layout(std430, binding = 11) readonly buffer EmptyCells { uint bits[]; } empty_cells;
layout(std430, binding = 12) writeonly buffer Image { vec4 px[]; } image;

#include "double_float.glsl"
#include "exp_neg.glsl"
#include "grid_sampler.glsl"
#include "transfer_function.glsl"
#include "shading.glsl"
#include "simpson_step.glsl"

#include "camera_rays.glsl"

DF u0[3], du[3];
vec3 d;

#include "empty_space.glsl"
#include "cell_walk.glsl"
#include "occupied_runs.glsl"

// (r, g, b, tau) at t, lit.
vec4 eval(float t) {
  DF u[3];
  const DF k = DF(t, 0.0);
  for (int a = 0; a < 3; ++a) u[a] = df_add(u0[a], df_mul(k, du[a]));
  const Cell cell = grid_cell(u);
  vec4 v = tf_at(interpolate(cell));
  if (p.lit != 0) {
    const Terms l = terms_of(gradient_at(cell), d);
    v.rgb = v.rgb * l.a + l.b;
  }
  return v;
}

// The last evaluations, found again by their exact t.
const int kCache = 12;
float cache_t[kCache];
vec4 cache_v[kCache];
int cache_used = 0, cache_next = -1;

vec4 cached(float t) {
  for (int i = 0; i < cache_used; ++i)
    if (cache_t[i] == t) return cache_v[i];
  cache_next = (cache_next + 1) % kCache;
  cache_used = max(cache_used, cache_next + 1);
  cache_t[cache_next] = t;
  cache_v[cache_next] = eval(t);
  return cache_v[cache_next];
}

vec4 f[5];  // the five samples of the current try
void sample_step(float t, float h) {
  for (int k = 0; k < 5; ++k) f[k] = cached(t + h * (0.25 * float(k)));
}

bool accepted(float err, float h) { return err <= p.tolerance * h / p.h0 || h <= p.hmin; }

// Algorithm 2's step control (simpson5.hpp, StepControl).
struct Control {
  float h;
  bool last_succeeded;
};
void succeeded(inout Control c) {
  if (c.last_succeeded) c.h = min(2.0 * c.h, p.hmax);
  c.last_succeeded = true;
}
void failed(inout Control c, float h_tried) {
  c.h = max(0.5 * h_tried, p.hmin);
  c.last_succeeded = false;
}

vec3 C = vec3(0.0);
float T = 1.0;
Control outer;

// The outer integral over [a, b] (simpson_step.glsl).
void outer_integral(float a, float b) {
  for (float u = a; u < b;) {
    const float h = min(outer.h, b - u);
    sample_step(u, h);
    const ColourStep st = colour_step(f, T, h);
    if (!accepted(colour_error(st), h)) {
      failed(outer, h);
      continue;
    }
    T = add_step(st, T, C);
    succeeded(outer);
    u = h >= b - u ? b : u + h;
  }
}

// Algorithm 3 over [t0, t_end] (AdaptiveSimpsonIntegrator's integrate_run).
void integrate_run(float t0, float t_end, float cutoff) {
  Control inner = Control(p.h0, true);
  outer = Control(p.h0, true);
  for (float t = t0; t < t_end && T >= cutoff;) {
    float h;
    for (;;) {
      h = min(inner.h, t_end - t);
      sample_step(t, h);
      if (accepted(tau_error(f, h), h)) break;
      failed(inner, h);
    }
    succeeded(inner);
    const float b = h >= t_end - t ? t_end : t + h;
    bool empty = true;
    for (int k = 0; k < 5; ++k) empty = empty && f[k].w == 0.0;
    if (!empty) {
      if (p.coupled != 0) outer = Control(h, true);
      outer_integral(t, b);
    }
    t = b;
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
  const float brightest = p.lit != 0 ? max(1.0, p.ka + p.kd + p.ks) : 1.0;
  const float cutoff = p.skip != 0 ? 0.1 * p.tolerance / brightest : 0.0;
  // The runs of non-empty macro cells (for_each_occupied_run).
  MacroWalk walk = macro_walk_start();
  MacroRun run;
  for (DF at = DF(0.0, 0.0); t_end.hi > 0.0 && df_less(at, t_end) && T >= cutoff && macro_next(walk, t_end, run);
       at = run.t_end)
    if (!run.empty && df_less(at, run.t_end)) integrate_run(df_float(at), df_float(run.t_end), cutoff);
  image.px[pixel] = vec4(C, 1.0 - T);
}
