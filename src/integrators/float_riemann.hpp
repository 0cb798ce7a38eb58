#pragma once
// riemann's float path (issue 8; docs/PERFORMANCE.md, "Float paths and packets"),
// unlit and lit (float_shading.hpp):
// RiemannIntegrator's sum (riemann.hpp) on the same sample positions, with the
// per-sample work in float. Sample k sits at grid position u0 + k du (in
// double, as the pre-integrated float paths, float_march.hpp), is interpolated
// by FloatSampler and classified by FloatTransferFunction; its step's opacity
// is 1 - exp(-tau h_k) with exp_neg below, and the steps are composited front
// to back in float. h_k = min(h, t1 - t_k) and the leaps over empty macro
// cells are taken in double, as on the double path. A pixel differs from the
// double path's by a few float roundings per step (tests bound it by 1e-4
// per channel on the bundled scenes); it depends only on its ray.
#include <algorithm>
#include <cmath>

#include "float_math.hpp"
#include "float_shading.hpp"
#include "ray_steps.hpp"
#include "vri/core/ray.hpp"
#include "vri/core/rgba.hpp"
#include "vri/tables/float_lookup.hpp"
#include "vri/transfer/float_transfer_function.hpp"
#include "vri/volume/float_sampler.hpp"

namespace vri::detail {

// One sample of riemann's float sum: its colour (lit: c a + b) weighted by
// the step's opacity, composited into (C, T).
inline void riemann_step(const FloatTransferFunction::Sample& v, float h_k, Float4& C, float& T) {
  const float e = exp_neg(v.tau * h_k);
  const float w = T * (1 - e);
  C += w * Float4{v.r, v.g, v.b, 0};
  T *= e;
}
inline void riemann_step(const FloatTransferFunction::Sample& v, const FloatShading::Terms& lit, float h_k, Float4& C,
                         float& T) {
  riemann_step({v.r * lit.a + lit.b, v.g * lit.a + lit.b, v.b * lit.a + lit.b, v.tau}, h_k, C, T);
}

// The head of a stretch of riemann's float march at sample k: a leap over the
// empty macro cells from t_k (k moves past them) until a sample in a
// non-empty run; returns the sample where the next query is due (k + 1 at
// least), or n once no query is needed. The packets run the same per lane.
inline long long riemann_head(const Leap& leap, const Ray& ray, const Interval& iv, double h, long long n,
                              long long& k) {
  if (!leap.space) return n;
  while (k < n) {
    const EmptySpace::Run run = leap.space->run(ray, iv.t0 + k * h, iv.t1);
    if (!run.empty)
      return std::clamp(static_cast<long long>(std::ceil((run.t_end - iv.t0) / h)), k + 1, n);
    k = std::max(k, static_cast<long long>(std::floor((run.t_end - iv.t0) / h))) + 1;  // samples up to t_end add nothing
  }
  return n;
}

// The number of samples of riemann on the clipped ray (at least one).
inline long long riemann_samples(const Interval& iv, double h) {
  return std::max(1LL, static_cast<long long>(std::ceil(iv.length() / h)));
}

// `values`: the volume's typed samples (GridVolume::visit); `shading`: null
// unlit, else the lighting of each sample (float_shading.hpp).
template <class Value>
Rgba march_riemann_float(const GridVolume& volume, const FloatSampler& sampler, const Value* values,
                         const FloatTransferFunction& tf, const FloatShading* shading, const Ray& ray, double h,
                         const Leap& leap) {
  const auto iv = clip_to_box(ray, volume.box_lo(), volume.box_hi());
  if (!iv) return {0, 0, 0, 0};
  const long long n = riemann_samples(*iv, h);
  const Vec3 u0 = sampler.grid(ray.at(iv->t0)), du = sampler.grid_step(ray.dir * h);
  const float termination = static_cast<float>(leap.termination);
  const FloatShading::Vector d = direction(ray);
  Float4 C = {0, 0, 0, 0};
  float T = 1;
  for (long long k = 0; k < n;) {
    const long long stop = riemann_head(leap, ray, *iv, h, n, k);
    for (; k < stop; ++k) {
      const double h_k = std::min(h, iv->t1 - (iv->t0 + k * h));
      if (T < termination || !(h_k > 0)) return {C[0], C[1], C[2], 1 - T};
      if (!shading) {
        riemann_step(tf(sampler.at(values, u0 + static_cast<double>(k) * du)), static_cast<float>(h_k), C, T);
        continue;
      }
      const FloatSampler::Cell cell = sampler.cell(u0 + static_cast<double>(k) * du);
      const float s = FloatSampler::interpolate(corners_as_float(values + cell.offset, sampler.stride_y(),
                                                                 sampler.stride_z()),
                                                cell.f);
      const FloatTransferFunction::Sample v = tf(s);
      if (v.tau == 0) continue;  // adds exactly nothing: no gradient needed
      riemann_step(v, shading->terms(shading->gradient(cell), d), static_cast<float>(h_k), C, T);
    }
  }
  return {C[0], C[1], C[2], 1 - T};
}

}  // namespace vri::detail
