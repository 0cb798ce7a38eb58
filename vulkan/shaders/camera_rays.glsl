// A per-pixel march's ray, made on the GPU from the camera as the CPU makes
// it (Camera::ray, clip_to_box, FloatSampler::grid), in double-float
// (double_float.glsl): a frame uploads the camera block of
// src/methods/march/ray_setup.hpp (a few hundred bytes), not a ray per pixel
// (~100 B a pixel: 1.87 GB at 4096^2, issue 47). The block is in a frame
// moved to the box's centre and scaled by a power of two to the box's size,
// so double-float's split neither overflows nor loses bits far from the
// origin; the power of two keeps ratios (samples per ray) and grid
// coordinates as the CPU's. Include after declaring `rays` (float r[]),
// the buffer that holds the block and, after it, `extras` floats a pixel
// (riemann's jitter fractions).

#include "camera_block.h"
const uint kCameraFloats = VRI_CAMERA_FLOATS;
const uint kCamEye = VRI_CAM_EYE, kCamU = VRI_CAM_U, kCamV = VRI_CAM_V, kCamW = VRI_CAM_W;
const uint kCamAspect = VRI_CAM_ASPECT, kCamHalfH = VRI_CAM_HALF_H, kCamBoxLo = VRI_CAM_BOX_LO;
const uint kCamBoxHi = VRI_CAM_BOX_HI, kCamOrigin = VRI_CAM_ORIGIN, kCamInverse = VRI_CAM_INVERSE;
const uint kCamStep = VRI_CAM_STEP, kCamScale = VRI_CAM_SCALE, kCamWidth = VRI_CAM_WIDTH;
const uint kCamHeight = VRI_CAM_HEIGHT, kCamFirst = VRI_CAM_FIRST, kCamOrtho = VRI_CAM_ORTHO;
const uint kCamExtras = VRI_CAM_EXTRAS, kCamPlanes = VRI_CAM_PLANES, kCamPlane0 = VRI_CAM_PLANE0;
const uint kCamKernelCuts = VRI_CAM_KERNEL_CUTS;

DF cam_df(uint slot) { return DF(rays.r[2u * slot], rays.r[2u * slot + 1u]); }
uint cam_uint(uint at) { return floatBitsToUint(rays.r[at]); }

// Float `at` of this dispatch's pixel `index`'s extras.
float pixel_extra(uint index, uint at) { return rays.r[kCameraFloats + index * cam_uint(kCamExtras) + at]; }

struct PixelRay {
  DF o[3], d[3];  // the frame's units; d unit length
  DF t0, t1;      // inside the box from t0 (>= 0) to t1
  bool hits;      // false: it misses the box (or only touches it)
};

// The ray r cut at the block's clip planes (SPEC §12 "clip", ClipRegion::cut;
// a grid's crop box is in the block's box): [t0, t1] narrowed where the ray
// crosses a plane, kept false where it runs parallel on the cut side.
void clip_window(PixelRay r, inout DF t0, inout DF t1, inout bool kept) {
  const uint planes = cam_uint(kCamPlanes);
  if (planes == 0xffffffffu) kept = false;
  for (uint i = 0u; i < min(planes, uint(VRI_CAM_MAX_PLANES)); ++i) {
    const uint at = kCamPlane0 + 4u * i;
    DF along = DF(0.0, 0.0), height = DF(0.0, 0.0);
    for (uint a = 0u; a < 3u; ++a) {
      along = df_add(along, df_mul(cam_df(at + a), r.d[a]));
      height = df_add(height, df_mul(cam_df(at + a), r.o[a]));
    }
    height = df_add(height, cam_df(at + 3u));
    if (along.hi == 0.0) {  // parallel: kept whole or cut whole
      if (height.hi < 0.0) kept = false;
      continue;
    }
    const DF t = df_neg(df_div(height, along));
    if (along.hi > 0.0) {
      if (df_less(t0, t)) t0 = t;
    } else {
      t1 = df_min(t1, t);
    }
  }
}

// The ray of the dispatch's pixel `index` (Camera::ray), clipped to the
// block's box (clip_to_box) and, unless the kernel cuts it itself, its clip
// planes (clip_window).
PixelRay pixel_ray(uint index) {
  PixelRay r;
  const uint width = cam_uint(kCamWidth), pixel = cam_uint(kCamFirst) + index;
  const DF one = DF(1.0, 0.0);
  // x = (2 (px + 0.5) / W - 1) half_h aspect, y = (1 - 2 (py + 0.5) / H) half_h.
  const DF fx = df_div(DF(2.0 * float(pixel % width) + 1.0, 0.0), DF(float(width), 0.0));
  const DF fy = df_div(DF(2.0 * float(pixel / width) + 1.0, 0.0), DF(float(cam_uint(kCamHeight)), 0.0));
  const DF x = df_mul(df_mul(df_sub(fx, one), cam_df(kCamHalfH)), cam_df(kCamAspect));
  const DF y = df_mul(df_sub(one, fy), cam_df(kCamHalfH));
  if (cam_uint(kCamOrtho) != 0u) {
    for (uint a = 0u; a < 3u; ++a) {
      r.o[a] = df_add(df_add(cam_df(kCamEye + a), df_mul(x, cam_df(kCamU + a))), df_mul(y, cam_df(kCamV + a)));
      r.d[a] = df_neg(cam_df(kCamW + a));
    }
  } else {
    DF q = DF(0.0, 0.0);
    for (uint a = 0u; a < 3u; ++a) {
      r.o[a] = cam_df(kCamEye + a);
      r.d[a] = df_sub(df_add(df_mul(x, cam_df(kCamU + a)), df_mul(y, cam_df(kCamV + a))), cam_df(kCamW + a));
      q = df_add(q, df_mul(r.d[a], r.d[a]));
    }
    const DF inverse = df_div(one, df_sqrt(q));  // normalize: d (1 / |d|)
    for (uint a = 0u; a < 3u; ++a) r.d[a] = df_mul(r.d[a], inverse);
  }
  r.t0 = DF(0.0, 0.0);
  r.t1 = DF(0.0, 0.0);
  r.hits = true;
  bool bounded = false;
  for (uint a = 0u; a < 3u; ++a) {
    const DF lo = cam_df(kCamBoxLo + a), hi = cam_df(kCamBoxHi + a);
    if (r.d[a].hi == 0.0) {  // parallel: inside the slab or a miss
      if (df_less(r.o[a], lo) || df_less(hi, r.o[a])) r.hits = false;
      continue;
    }
    DF ta = df_div(df_sub(lo, r.o[a]), r.d[a]), tb = df_div(df_sub(hi, r.o[a]), r.d[a]);
    if (df_less(tb, ta)) {
      const DF swap = ta;
      ta = tb;
      tb = swap;
    }
    if (df_less(r.t0, ta)) r.t0 = ta;
    r.t1 = bounded ? df_min(r.t1, tb) : tb;
    bounded = true;
  }
  if (cam_uint(kCamKernelCuts) == 0u) clip_window(r, r.t0, r.t1, r.hits);
  // A camera absurdly far from the box (over ~1e34 of its sizes) overflows: a miss.
  r.hits = r.hits && bounded && df_less(r.t0, r.t1) && !isinf(r.t1.hi);
  return r;
}

// The ray's length inside the box, world units.
DF world_length(PixelRay r) { return df_div(df_sub(r.t1, r.t0), cam_df(kCamScale)); }

// Where the ray enters the grid, grid units, and the grid's step along it
// for `per` frame units (the march's step; the scale: a world unit).
void grid_entry(PixelRay r, DF per, out DF entry[3], out DF step[3]) {
  for (uint a = 0u; a < 3u; ++a) {
    const DF inverse = cam_df(kCamInverse + a);
    entry[a] = df_mul(df_sub(df_add(r.o[a], df_mul(r.t0, r.d[a])), cam_df(kCamOrigin + a)), inverse);
    step[a] = df_mul(df_mul(r.d[a], per), inverse);
  }
}

// The direction in float (the CPU's detail::direction).
vec3 float_direction(PixelRay r) { return vec3(df_float(r.d[0]), df_float(r.d[1]), df_float(r.d[2])); }
