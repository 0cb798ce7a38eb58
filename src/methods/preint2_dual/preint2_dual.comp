#version 450
// preint2-dual on the GPU (SPEC §9; El Hajjar, Marchesin, Dischler &
// Mongenet 2008, §4), as the CPU's float path (src/methods/preint2_dual/dual_march.hpp,
// march_cells_float): the ray is cut where it crosses cell faces
// (Amanatides & Woo, as cell_traversal.hpp: plane crossings recomputed from
// their integer index, each piece's cell taken at its midpoint and clamped)
// and each piece - one slab inside one cell, where the trilinear signal is a
// cubic - is sampled at its front, middle and back from the cell's eight
// corners, looked up in the (l, s_f, s_m, s_b) table (the paper's 4D table:
// `lengths` slices from 0 to max_length, linear in l) and composited front to
// back. The walk (cell_walk.glsl) is in double-float from the ray's entry,
// so the pieces are the CPU's up to roundings. Lit as preint2 (p.lit: 1 sampled, 2
// interpolated with the middle and back weighted tables). A piece whose
// cell's macro cell is empty (classified for second-order entries) adds
// exactly nothing: the walk leaps to where the ray leaves that macro cell
// (p.skip).
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;

#include "grid_params.glsl"
#include "preint2_dual_push_constants.h"
layout(push_constant) uniform Params { VRI_PREINT2_DUAL_PUSH_CONSTANTS } p;

#include "split_array.glsl"
SPLIT_INPUT(uint, volume, 0, 2u, 0)
// The tables, slice after slice: unlit and sampled the table; interpolated
// the full, middle and back weighted tables.
SPLIT_INPUT(vec4, table, 4, 4u, 1)
SPLIT_INPUT(vec4, weighted1, 8, 4u, 2)
SPLIT_INPUT(vec4, weighted2, 12, 4u, 3)
SPLIT_INPUT(float, gradients, 16, 2u, 4)  // lit only
// The camera block each ray is made from (camera_rays.glsl,
// src/methods/march/ray_setup.hpp).
layout(std430, binding = 20) readonly buffer Rays { float r[]; } rays;
layout(std430, binding = 21) readonly buffer EmptyCells { uint bits[]; } empty_cells;
layout(std430, binding = 22) writeonly buffer Image { vec4 px[]; } image;

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
#include "cell_walk.glsl"

// The table at slab length l and scalars (s_f, s_m, s_b): the two slices
// around l (length_bracket, slab_table.hpp) blended first, entry by entry,
// then along s_m, s_f and s_b last (DualFloatLookup::blend's order,
// src/methods/preint2_dual/dual_march.hpp).
vec4 lookup(int which, float l, Place f, Place m, Place b) {
  const Place at = length_place(l, p.max_length, p.lengths);
  const uint n = uint(p.table_n), row = n, plane = n * n, slice = n * plane;
  const uint first = uint(at.i) * slice + uint(f.i) * plane + uint(m.i) * row + uint(b.i);
  vec4 e[2];  // entries b and b + 1
  for (uint k = 0u; k < 2u; ++k) {
    const uint x = first + k;
    const vec4 r00 = between(entry_of(which, x), entry_of(which, x + slice), at);
    const vec4 r01 = between(entry_of(which, x + row), entry_of(which, x + row + slice), at);
    const vec4 r10 = between(entry_of(which, x + plane), entry_of(which, x + plane + slice), at);
    const vec4 r11 = between(entry_of(which, x + plane + row), entry_of(which, x + plane + row + slice), at);
    precise vec4 c0 = r00 + m.w * (r01 - r00);
    precise vec4 c1 = r10 + m.w * (r11 - r10);
    precise vec4 v = c0 + f.w * (c1 - c0);
    e[k] = v;
  }
  precise vec4 v = e[0] + b.w * (e[1] - e[0]);
  return v;
}

void main() {
  const uint pixel = PIXEL_INDEX();
  if (pixel >= p.pixels) return;
  // The ray from its entry into the box: u0 + t du, t in world units up to t_end (< 0: a miss).
  const PixelRay ray = pixel_ray(pixel);
  grid_entry(ray, cam_df(kCamScale), u0, du);  // finite on a miss too
  const DF t_end = ray.hits ? world_length(ray) : DF(-1.0, 0.0);
  d = float_direction(ray);
  FrontToBack acc = ftb_start();
  CellWalk w = walk_start();
  while (t_end.hi > 0.0 && df_less(w.ta, t_end)) {
    if (ftb_below(acc, GRID_TERMINATION)) break;
    const DF ta = w.ta, tb = walk_next(w, t_end);
    w.ta = tb;
    if (df_less(ta, tb)) {
      const DF tm = df_mul(df_add(ta, tb), DF(0.5, 0.0));
      const DF t3[3] = DF[3](ta, tm, tb);
      Cell cell[3];
      const ivec3 index = piece_cell(ta, tb);
      const uint offset = uint(index.x) + p.sy * uint(index.y) + p.sz * uint(index.z);
      for (int k = 0; k < 3; ++k) {
        cell[k].offset = offset;
        cell[k].index = index;
        cell[k].f = clamp(local_in(index, t3[k]), 0.0, 1.0);
      }
      if (!macro_empty(cell[0])) {
        const DF length = df_sub(tb, ta);
        const float l = length.hi + length.lo;
        Place place3[3];
        vec3 g[3];
        for (int k = 0; k < 3; ++k) {
          place3[k] = place(interpolate(cell[k]));
          g[k] = p.lit != 0 ? gradient_at(cell[k]) : vec3(0.0);
        }
        vec4 v;
        if (p.lit == 0) {
          v = lookup(0, l, place3[0], place3[1], place3[2]);
        } else if (p.lit == 1) {
          precise vec3 sum = (g[0] + g[1]) + g[2];
          precise vec3 mean = sum * uintBitsToFloat(0x3eaaaaabu);  // 1.0f / 3, as the CPU's mean
          const Terms t = terms_of(mean, d);
          const vec4 e = lookup(0, l, place3[0], place3[1], place3[2]);
          precise vec3 c = e.rgb * t.a + t.b * e.a;
          v = vec4(c, e.a);
        } else {
          const Terms tf = terms_of(g[0], d), tm2 = terms_of(g[1], d), tb2 = terms_of(g[2], d);
          const vec4 full = lookup(0, l, place3[0], place3[1], place3[2]);
          const vec4 middle = lookup(1, l, place3[0], place3[1], place3[2]);
          const vec4 back = lookup(2, l, place3[0], place3[1], place3[2]);
          precise float s_f = (full.a - middle.a) - back.a;
          precise float specular = (tf.b * s_f + tm2.b * middle.a) + tb2.b * back.a;
          precise vec3 d_f = (full.rgb - middle.rgb) - back.rgb;
          precise vec3 c = ((tf.a * d_f + tm2.a * middle.rgb) + tb2.a * back.rgb) + specular;
          v = vec4(c, full.a);
        }
        ftb_add(acc, v);
      } else {
        walk_leap(w, index, t_end);
      }
    }
  }
  image.px[pixel] = ftb_pixel(acc);
}
