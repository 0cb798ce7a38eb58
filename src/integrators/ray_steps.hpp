#pragma once
// Uniform ray stepping shared by the pre-integrated ray casters (preint1,
// preint2): the ray clipped to the volume box is sampled at t0 + i h, cut into
// slabs of Samples - 1 steps (one table lookup each), and each slab's back
// sample is the next slab's front. The remaining length r < (Samples - 1) h is
// the partial slab: it is cut into Samples - 1 equal sub-slabs of length
// r / (Samples - 1) < h, each integrated exactly under the table's
// discretisation with the scalar linear along it (exact_slab), so it is neither
// dropped nor counted twice and adds no length interpolation error.
#include <array>
#include <cmath>
#include <string>

#include "vri/core/error.hpp"
#include "vri/core/ray.hpp"
#include "vri/core/rgba.hpp"
#include "vri/tables/discrete_tf.hpp"
#include "vri/tables/slab_integral.hpp"
#include "vri/volume/grid_volume.hpp"

namespace vri::detail {

// The step h in world units; `step` is in voxel units (1e-4 .. 1e4).
inline double world_step(const GridVolume& volume, double step, const std::string& method) {
  if (!(step >= 1e-4 && step <= 1e4))
    throw Error(method + ": step must be in [1e-4, 1e4] voxel units, got " + std::to_string(step));
  return step * volume.voxel_unit();
}

// Front-to-back compositing of premultiplied slabs.
struct FrontToBack {
  double T = 1, C[3] = {0, 0, 0};
  void add(double r, double g, double b, double a) {
    C[0] += T * r;
    C[1] += T * g;
    C[2] += T * b;
    T *= 1 - a;
  }
  Rgba result() const { return {C[0], C[1], C[2], 1 - T}; }
};

// Marches `ray` in slabs of Samples - 1 steps of h (world units) and composites
// lookup(s) -> Rgba for every full slab, s holding its Samples scalars front to
// back, then the partial slab as described above. The next slab's samples are
// taken before the current lookup and handed to prefetch(s), so a large table
// can start loading its entries while this slab is composited.
struct NoPrefetch {
  template <class S>
  void operator()(const S&) const {}
};

template <int Samples, class Lookup, class Prefetch = NoPrefetch>
Rgba march_uniform_slabs(const GridVolume& volume, const DiscreteTf& tf, const Ray& ray, double h, Lookup&& lookup,
                         Prefetch&& prefetch = {}) {
  static_assert(Samples >= 2);
  constexpr int steps = Samples - 1;
  const auto iv = clip_to_box(ray, volume.box_lo(), volume.box_hi());
  if (!iv) return {0, 0, 0, 0};
  const double slab = steps * h;
  const long long full = static_cast<long long>(std::floor(iv->length() / slab));
  using Scalars = std::array<double, Samples>;
  const auto fill = [&](Scalars& s, long long k) {
    for (int i = 1; i < Samples; ++i) s[i] = volume.sample(ray.at(iv->t0 + (k * steps + i) * h));
  };
  FrontToBack acc;
  Scalars s{}, next{};
  s[0] = volume.sample(ray.at(iv->t0));
  if (full > 0) fill(s, 0);
  for (long long k = 0; k < full; ++k) {
    next[0] = s[steps];
    if (k + 1 < full) {
      fill(next, k + 1);
      prefetch(next);
    }
    const Rgba v = lookup(s);
    acc.add(v[0], v[1], v[2], v[3]);
    s = next;
  }
  const double t_rest = iv->t0 + full * steps * h;
  const double sub = (iv->t1 - t_rest) / steps;
  if (sub > 0)
    for (int i = 1; i <= steps; ++i) {
      const double s_back = volume.sample(ray.at(i == steps ? iv->t1 : t_rest + i * sub));
      const SlabRgba v = exact_slab(tf, s[0], s_back, sub);
      acc.add(v.r, v.g, v.b, v.a);
      s[0] = s_back;
    }
  return acc.result();
}

}  // namespace vri::detail
