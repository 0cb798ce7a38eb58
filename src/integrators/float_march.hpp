#pragma once
// preint1's float path (issue 8; docs/PERFORMANCE.md, "Interactive speed"):
// march_uniform_slabs<2> with the Unlit policy (ray_steps.hpp,
// slab_policies.hpp) on the same sample positions, with the per-sample work
// in float. Sample k sits at grid position u0 + k du (u0 the ray's entry,
// du = h dir / spacing, in double: one multiply-add per axis, the same point
// whether the ray got there step by step or by a leap), is interpolated by
// FloatSampler, each slab is one FloatLookup of the first-order table (found
// one slab ahead, so its entries load while the slab before is composited), and
// the slabs are composited front to back in float. The partial last slab is
// integrated exactly as on the double path (exact_slab). Leaps over empty
// macro cells and early termination are those of march_uniform_slabs.
//
// Against the double path a pixel changes by a few float roundings per slab;
// tests/integrators/fast_path_test.cpp bounds it by 1e-4 per channel on the
// bundled scenes. Each pixel depends only on its ray: same bytes for any
// thread count.
#include <algorithm>
#include <cmath>
#include <limits>

#include "ray_steps.hpp"
#include "vri/core/ray.hpp"
#include "vri/core/rgba.hpp"
#include "vri/tables/float_lookup.hpp"
#include "vri/tables/slab_integral.hpp"
#include "vri/volume/float_sampler.hpp"

namespace vri::detail {

// The end of a float march: the pixel (C, 1 - T) once T < termination, else
// with the partial last slab from the front sample s_front (the sample of slab
// `full`) to the exit iv.t1 integrated exactly, as on the double path.
template <class Value>
Rgba finish_preint1_float(const FloatSampler& sampler, const Value* values, const DiscreteTf& tf, const Ray& ray,
                          const Interval& iv, long long full, double h, float s_front, float termination, Float4 C,
                          float T) {
  const double sub = iv.t1 - (iv.t0 + full * h);
  if (!(T < termination) && sub > 0) {
    const SlabRgba v = exact_slab(tf, s_front, sampler.at(values, sampler.grid(ray.at(iv.t1))), sub);
    C += T * Float4{static_cast<float>(v.r), static_cast<float>(v.g), static_cast<float>(v.b), 0};
    T *= 1 - static_cast<float>(v.a);
  }
  return {C[0], C[1], C[2], 1 - T};
}

// `values`: the volume's typed samples (GridVolume::visit).
template <class Value>
Rgba march_preint1_float(const GridVolume& volume, const FloatSampler& sampler, const Value* values,
                         const FloatLookup& table, const DiscreteTf& tf, const Ray& ray, double h, const Leap& leap) {
  const auto iv = clip_to_box(ray, volume.box_lo(), volume.box_hi());
  if (!iv) return {0, 0, 0, 0};
  const long long full = static_cast<long long>(std::floor(iv->length() / h));
  const Vec3 u0 = sampler.grid(ray.at(iv->t0)), du = sampler.grid_step(ray.dir * h);
  struct Point {
    float s;
    FloatLookup::Place place;
  };
  const auto sample = [&](long long k) {
    const float s = sampler.at(values, u0 + static_cast<double>(k) * du);
    return Point{s, table.place(s)};
  };
  const float termination = static_cast<float>(leap.termination);
  Float4 C = {0, 0, 0, 0};
  float T = 1;
  const auto result = [&] { return Rgba{C[0], C[1], C[2], 1 - T}; };
  // Samples k and k + 1 are in hand at slab k, and the table spot of slab k
  // found; sample k + 2 is taken and slab k + 1's spot found (its entries
  // start loading) before slab k is composited.
  Point front = sample(0), back = full > 0 ? sample(1) : front;
  FloatLookup::Spot spot = table.find(front.place, back.place);
  double t_check = -std::numeric_limits<double>::infinity();  // no leap query before this t
  for (long long k = 0; k < full;) {
    if (const long long j = leap_target(leap, ray, *iv, h, 1, k, full, t_check); j > k) {
      k = j;
      front = sample(k);
      if (k == full) break;
      back = sample(k + 1);
      spot = table.find(front.place, back.place);
    }
    // Slabs k .. stop - 1 start before t_check, where the next leap query is
    // due (all of them without skipping): they need no query.
    const long long stop =
        leap.space ? std::clamp(static_cast<long long>(std::ceil((t_check - iv->t0) / h)), k + 1, full) : full;
    for (; k < stop; ++k) {
      if (T < termination) return result();
      const Point next = k + 2 <= full ? sample(k + 2) : back;
      const FloatLookup::Spot following = table.find(back.place, next.place);
      const Float4 v = table.blend(spot);
      C += T * v;
      T *= 1 - v[3];
      front = back;
      back = next;
      spot = following;
    }
  }
  return finish_preint1_float(sampler, values, tf, ray, *iv, full, h, front.s, termination, C, T);
}

}  // namespace vri::detail
