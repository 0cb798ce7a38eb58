#pragma once
// riemann's float path (issue 8; docs/PERFORMANCE.md, "Float paths and packets"),
// unlit and lit (float_shading.hpp):
// RiemannIntegrator's sum (riemann.hpp) on the same sample positions, with the
// per-sample work in float. Sample k sits at grid position u0 + k du (in
// double, as the pre-integrated float paths, float_march.hpp), is interpolated
// by FloatSampler and classified by FloatTransferFunction; its step's opacity
// is 1 - exp(-tau h_k) with exp_neg below, and the steps are composited front
// to back in double (FrontToBack, ray_steps.hpp). h_k = min(h, t1 - t_k) and the leaps over empty macro
// cells are taken in double, as on the double path. A pixel differs from the
// double path's by a few float roundings per step (tests bound it by 1e-4
// per channel on the bundled scenes); it depends only on its ray.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>

#include "methods/march/float_math.hpp"
#include "methods/march/float_shading.hpp"
#include "methods/march/ray_steps.hpp"
#include "vri/geometry.hpp"
#include "tables/float_lookup.hpp"
#include "transfer/float_transfer_function.hpp"
#include "volume/float_sampler.hpp"

namespace vri::detail {

// One sample of riemann's float sum: its colour (lit: c a + b) weighted by
// the step's opacity, composited into acc.
inline void riemann_step(const FloatTransferFunction::Sample& v, float h_k, FrontToBack& acc) {
  acc.add_step(v.r, v.g, v.b, exp_neg(v.tau * h_k));
}
inline void riemann_step(const FloatTransferFunction::Sample& v, const FloatShading::Terms& lit, float h_k,
                         FrontToBack& acc) {
  riemann_step({v.r * lit.a + lit.b, v.g * lit.a + lit.b, v.b * lit.a + lit.b, v.tau}, h_k, acc);
}

// Jitter (riemann.hpp): u in [0, 1) from the bits of the ray and the seed,
// through splitmix64 (Steele, Lea & Flood 2014), so equal rays get equal u.
inline double jitter_fraction(const Ray& ray, std::uint64_t seed) {
  auto mix = [](std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  std::uint64_t h = mix(seed);
  for (const double v : {ray.origin.x, ray.origin.y, ray.origin.z, ray.dir.x, ray.dir.y, ray.dir.z})
    h = mix(h ^ std::bit_cast<std::uint64_t>(v));
  return static_cast<double>(h >> 11) * 0x1p-53;
}

// The last sample at or before t_end of the steps of h from iv.t0 whose
// samples sit u h into their step (u = 0: at its front; with jitter, u of
// jitter_fraction; the partial last step's sample lies before that).
inline long long last_sample_before(double t_end, const Interval& iv, double h, double u) {
  return static_cast<long long>(std::floor((t_end - iv.t0) / h - u));
}

// The head of a stretch of riemann's float march at sample k: a leap over the
// empty macro cells (`runs`, the ray's) from sample k's place (k moves past
// them) until a sample in a non-empty run; returns the sample where the next
// query is due (k + 1 at least), or n once no query is needed (at once
// without skipping). The runs are
// asked where the samples lie, u h into their steps (the partial last step's
// u h_k), not at the steps' fronts: an empty run that ends between a front
// and its sample does not hold the sample. The packets run the same per lane.
inline long long riemann_head(MacroRuns& runs, const Interval& iv, double h, long long n, long long& k,
                              double u = 0) {
  if (!runs.skipping()) return n;
  while (k < n) {
    const double t_k = iv.t0 + k * h;
    const EmptySpace::Run run = runs.at(t_k + u * std::min(h, iv.t1 - t_k));
    if (!run.empty)
      return std::clamp(static_cast<long long>(std::ceil((run.t_end - iv.t0) / h - u)), k + 1, n);
    k = std::max(k, last_sample_before(run.t_end, iv, h, u)) + 1;  // samples up to t_end add nothing
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
                         const Leap& leap, std::optional<std::uint64_t> jitter = {}) {
  const auto iv = volume.clip(ray);
  if (!iv) return {0, 0, 0, 0};
  const double u = jitter ? jitter_fraction(ray, *jitter) : 0.0;  // the sample's place in its step
  const PieceRange owned = owned_pieces(*iv, h, riemann_samples(*iv, h));
  const long long n = owned.end;
  const Vec3 u0 = sampler.grid(ray.at(iv->t0)), du = sampler.grid_step(ray.dir * h);
  const FloatShading::Vector d = direction(ray);
  FrontToBack acc;
  MacroRuns runs(leap.space, ray, iv->t1);
  for (long long k = owned.begin; k < n;) {
    const long long stop = riemann_head(runs, *iv, h, n, k, u);
    for (; k < stop; ++k) {
      const double h_k = std::min(h, iv->t1 - (iv->t0 + k * h));
      if (acc.T < leap.termination || !(h_k > 0)) return acc.result();
      // u of the way into the step; only the partial last step is shorter than h.
      const Vec3 at = u0 + (static_cast<double>(k) + (h_k < h ? u * h_k / h : u)) * du;
      if (!shading) {
        riemann_step(tf(sampler.at(values, at)), static_cast<float>(h_k), acc);
        continue;
      }
      const FloatSampler::Cell cell = sampler.cell(at);
      const float s = FloatSampler::interpolate(corners_as_float(values + cell.offset, sampler.stride_y(),
                                                                 sampler.stride_z()),
                                                cell.f);
      const FloatTransferFunction::Sample v = tf(s);
      if (v.tau == 0) continue;  // adds exactly nothing: no gradient needed
      riemann_step(v, shading->terms(shading->gradient(cell), d), static_cast<float>(h_k), acc);
    }
  }
  return acc.result();
}

}  // namespace vri::detail
