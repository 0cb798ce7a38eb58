#pragma once
// riemann's float path (issue 8; docs/PERFORMANCE.md, "Interactive speed"):
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
#include <bit>
#include <cmath>
#include <cstdint>

#include "ray_steps.hpp"
#include "vri/core/ray.hpp"
#include "vri/core/rgba.hpp"
#include "vri/tables/float_lookup.hpp"
#include "vri/transfer/float_transfer_function.hpp"
#include "vri/volume/float_sampler.hpp"

namespace vri::detail {

// exp(-x) for x >= 0 in float, to about one ulp: Cody and Waite's reduction
// x = n ln 2 + r (ln 2 split in two parts), the degree-6 polynomial of
// Cephes' expf on |r| <= ln 2 / 2, then 2^n from the exponent bits; below
// e^-87 (under float's normal range) it returns about 1.6e-38, which makes
// an opacity of 1. The ray packets (float_packet.cpp, exp_neg8) do the same
// operations in the same order on 8 lanes: keep the two in step.
namespace exp_poly {
inline constexpr float kMin = -87.0f, kLog2e = 1.44269504088896341f;
inline constexpr float kLn2Hi = 0.693359375f, kLn2Lo = -2.12194440e-4f;
inline constexpr float kP[6] = {1.9875691500e-4f, 1.3981999507e-3f, 8.3334519073e-3f,
                                4.1665795894e-2f, 1.6666665459e-1f, 5.0000001201e-1f};
}  // namespace exp_poly

inline float exp_neg(float x) {
  using namespace exp_poly;
  const float y = std::max(-x, kMin);
  const float n = std::floor(y * kLog2e + 0.5f);
  const float r = (y - n * kLn2Hi) - n * kLn2Lo;
  float p = kP[0];
  for (int i = 1; i < 6; ++i) p = p * r + kP[i];
  const float e = (p * (r * r) + r) + 1.0f;
  return e * std::bit_cast<float>(static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<int>(n) + 127) << 23));
}

// One sample of riemann's float sum: its colour weighted by the step's
// opacity, composited into (C, T).
inline void riemann_step(const FloatTransferFunction::Sample& v, float h_k, Float4& C, float& T) {
  const float e = exp_neg(v.tau * h_k);
  const float w = T * (1 - e);
  C += w * Float4{v.r, v.g, v.b, 0};
  T *= e;
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

// `values`: the volume's typed samples (GridVolume::visit).
template <class Value>
Rgba march_riemann_float(const GridVolume& volume, const FloatSampler& sampler, const Value* values,
                         const FloatTransferFunction& tf, const Ray& ray, double h, const Leap& leap) {
  const auto iv = clip_to_box(ray, volume.box_lo(), volume.box_hi());
  if (!iv) return {0, 0, 0, 0};
  const long long n = riemann_samples(*iv, h);
  const Vec3 u0 = sampler.grid(ray.at(iv->t0)), du = sampler.grid_step(ray.dir * h);
  const float termination = static_cast<float>(leap.termination);
  Float4 C = {0, 0, 0, 0};
  float T = 1;
  for (long long k = 0; k < n;) {
    const long long stop = riemann_head(leap, ray, *iv, h, n, k);
    for (; k < stop; ++k) {
      const double h_k = std::min(h, iv->t1 - (iv->t0 + k * h));
      if (T < termination || !(h_k > 0)) return {C[0], C[1], C[2], 1 - T};
      riemann_step(tf(sampler.at(values, u0 + static_cast<double>(k) * du)), static_cast<float>(h_k), C, T);
    }
  }
  return {C[0], C[1], C[2], 1 - T};
}

}  // namespace vri::detail
