#version 450
// preint1 on the GPU (SPEC §9; Engel, Kraus & Ertl 2001; the CPU's float
// path, src/integrators/float_march.hpp): samples at u0 + i du, each slab
// between two samples one lookup of the pre-integration table at
// (s_i, s_i+1), composited front to back, C += T c, T *= 1 - alpha. Lit
// (SPEC §5, p.lit): `sampled` lights the slab's colour with the mean of its
// two gradients, `interpolated` (Lum, Wilson & Ma 2004) weights the terms at
// its two samples with the front- and back-weighted tables. The last,
// partial slab (shorter than the step) is integrated exactly on the host, as
// on the CPU (last_slabs), and arrives with the ray (host/ray_setup.cpp).
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;

#include "grid_params.glsl"
layout(push_constant) uniform Params {
  GRID_PARAMS
  int table_n;  // entries a side
  float table_lo, table_scale;
  int lit;  // 0: unlit, 1: sampled, 2: interpolated
  float ka, kd, ks, shininess, flat_threshold;
} p;

layout(std430, binding = 0) readonly buffer Volume { uint words[]; } volume;
layout(std430, binding = 1) readonly buffer Table { vec4 e[]; } table;
// Per ray (ray_setup.hpp, kPreint1RayFloats): u0 (hi x3, lo x3), du (hi x3,
// lo x3), the number of whole slabs (int bits), the last slab's premultiplied
// (r, g, b, alpha), the direction (x, y, z).
layout(std430, binding = 2) readonly buffer Rays { float r[]; } rays;
layout(std430, binding = 3) readonly buffer Gradients { float g[]; } gradients;      // lit only
layout(std430, binding = 4) readonly buffer FrontTable { vec4 e[]; } front_table;  // interpolated only
layout(std430, binding = 5) readonly buffer BackTable { vec4 e[]; } back_table;    // interpolated only
layout(std430, binding = 6) writeonly buffer Image { vec4 px[]; } image;

vec4 entry_of(int which, int e) { return which == 0 ? table.e[e] : which == 1 ? front_table.e[e] : back_table.e[e]; }

#include "double_float.glsl"
#include "exp_neg.glsl"
#include "grid_sampler.glsl"
#include "table_lookup.glsl"
#include "shading.glsl"

const uint kRayFloats = 20u;

DF u0[3], du[3];
vec3 d;

struct Sample {
  Place place;
  vec3 g;   // lit: the gradient
  Terms t;  // interpolated: the terms
};

Sample sample_at(int i) {
  DF u[3];
  const DF k = DF(float(i), 0.0);
  for (int a = 0; a < 3; ++a) u[a] = df_add(u0[a], df_mul(k, du[a]));
  const Cell cell = grid_cell(u);
  Sample out_s;
  out_s.place = place(interpolate(cell));
  out_s.g = vec3(0.0);
  out_s.t = Terms(0.0, 0.0);
  if (p.lit != 0) out_s.g = gradient_at(cell);
  if (p.lit == 2) out_s.t = terms_of(out_s.g, d);
  return out_s;
}

// The slab from f to b, lit as p.lit says (float_march.hpp, slab_colour).
vec4 slab(Sample f, Sample b) {
  if (p.lit == 0) return blend(0, f.place, b.place);
  if (p.lit == 1) {
    const vec4 v = blend(0, f.place, b.place);
    precise vec3 sum = f.g + b.g;
    precise vec3 g = sum * 0.5;
    const Terms t = terms_of(g, d);
    precise vec3 c = v.rgb * t.a + t.b * v.a;
    return vec4(c, v.a);
  }
  const vec4 fw = blend(1, f.place, b.place), bw = blend(2, f.place, b.place);
  precise float specular = f.t.b * (fw.a - bw.a) + b.t.b * bw.a;
  precise vec3 c = f.t.a * fw.rgb + b.t.a * bw.rgb + specular;
  return vec4(c, fw.a);
}

void main() {
  const uint pixel = PIXEL_INDEX();
  if (pixel >= p.pixels) return;
  const uint b = pixel * kRayFloats;
  for (int a = 0; a < 3; ++a) {
    u0[a] = DF(rays.r[b + a], rays.r[b + 3 + a]);
    du[a] = DF(rays.r[b + 6 + a], rays.r[b + 9 + a]);
  }
  d = vec3(rays.r[b + 17u], rays.r[b + 18u], rays.r[b + 19u]);
  const int full = floatBitsToInt(rays.r[b + 12u]);
  const vec4 tail = vec4(rays.r[b + 13u], rays.r[b + 14u], rays.r[b + 15u], rays.r[b + 16u]);
  precise vec4 C = vec4(0.0);
  precise float T = 1.0;
  if (full >= 0) {  // -1: the ray misses the volume
    Sample front = sample_at(0);
    for (int k = 0; k < full; ++k) {
      if (T < p.termination) break;
      const Sample back = sample_at(k + 1);
      const vec4 v = slab(front, back);
      C += T * v;
      T *= 1.0 - v.a;
      front = back;
    }
    if (!(T < p.termination)) {
      C += T * vec4(tail.rgb, 0.0);
      T *= 1.0 - tail.a;
    }
  }
  image.px[pixel] = vec4(C.rgb, 1.0 - T);
}
