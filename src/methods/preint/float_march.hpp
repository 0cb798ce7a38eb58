#pragma once
// The float paths of preint1 and preint2 (issue 8; docs/PERFORMANCE.md,
// "Float paths and packets"): march_uniform_slabs with the slab policies
// (ray_steps.hpp, slab_policies.hpp: unlit, sampled, interpolated) on the
// same sample positions, with the per-sample work in float. Sample i sits at grid position u0 + i du (u0 the
// ray's entry, du = h dir / spacing, in double: one multiply-add per axis, the
// same point whether the ray got there step by step or by a leap), is
// interpolated by FloatSampler and placed on the table axis once; each slab
// (Lookup::kSteps steps: FloatLookup for preint1, SecondOrderFloatLookup for
// preint2) is one float lookup, found one slab ahead so its entries load while
// the slab before is composited, and the float slabs are composited front to
// back in double (FrontToBack, ray_steps.hpp). The partial last slab is integrated exactly as on the double path
// (exact_slab, cut into kSteps linear sub-slabs). Leaps over empty macro cells
// and early termination are those of march_uniform_slabs.
//
// Against the double path a pixel changes by a few float roundings per slab;
// tests/methods/fast_path_test.cpp bounds it by 1e-4 per channel on the
// bundled scenes. Each pixel depends only on its ray: same bytes for any
// thread count.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "methods/march/float_shading.hpp"
#include "methods/march/ray_steps.hpp"
#include "vri/geometry.hpp"
#include "shading/lit_slab.hpp"
#include "tables/float_lookup.hpp"
#include "tables/slab_integral.hpp"
#include "tables/weighted_tables.hpp"
#include "volume/float_sampler.hpp"

namespace vri::detail {

// How a float march lights its slabs (SPEC §5; docs/LIGHTING.md): unlit
// (no shading), `sampled` (one normal per slab, the mean of its samples'
// gradients, lighting the pre-integrated colour: lit_by) or `interpolated`
// (the shading terms at each sample times the tables weighted toward it:
// preint1's front and back tables, lit_weighted, Lum, Wilson & Ma 2004;
// preint2's full, middle and back tables, lit_lagrange). The weighted tables
// have the layout of the march's lookup table, so one spot serves them all.
struct FloatLighting {
  const FloatShading* shading = nullptr;         // null: unlit
  std::array<const float*, 3> weighted = {};     // interpolated: the tables' data, front to back
  bool interpolated() const { return weighted[0] != nullptr; }
};

// A sample of a float march: the scalar and, lit, the gradient there
// (`sampled`) or the shading terms (`interpolated`).
struct FloatSample {
  float s;
  FloatShading::Vector g;
  FloatShading::Terms t;
};
template <class Value>
FloatSample sample_at(const FloatSampler& sampler, const Value* values, const FloatLighting& lighting,
                      const FloatShading::Vector& d, Vec3 u) {
  if (!lighting.shading) return {sampler.at(values, u), {}, {}};
  const FloatSampler::Cell cell = sampler.cell(u);
  FloatSample out{FloatSampler::interpolate(corners_as_float(values + cell.offset, sampler.stride_y(),
                                                             sampler.stride_z()),
                                            cell.f),
                  lighting.shading->gradient(cell), {}};
  if (lighting.interpolated()) out.t = lighting.shading->terms(out.g, d);
  return out;
}

// The mean of a slab's gradients (its one normal in `sampled`), summed front
// to back.
template <std::size_t N>
FloatShading::Vector mean(const std::array<FloatShading::Vector, N>& g) {
  FloatShading::Vector sum = g[0];
  for (std::size_t i = 1; i < N; ++i)
    for (int a = 0; a < 3; ++a) sum[a] = sum[a] + g[i][a];
  for (int a = 0; a < 3; ++a) sum[a] = sum[a] * (1.0f / N);
  return sum;
}
// A slab's colour and opacity from its table spot and its samples p (each
// p[i].sample a FloatSample, front to back), lit as `lighting` says.
template <class Lookup, class Point, std::size_t N>
Float4 slab_colour(const Lookup& table, const typename Lookup::Spot& spot, const std::array<Point, N>& p,
                   const FloatLighting& lighting, const FloatShading::Vector& d) {
  if (!lighting.shading) return table.blend(spot);
  if (!lighting.interpolated()) {
    std::array<FloatShading::Vector, N> g;
    for (std::size_t i = 0; i < N; ++i) g[i] = p[i].sample.g;
    return lit_by(lighting.shading->terms(mean(g), d), table.blend(spot));
  }
  if constexpr (N == 2)
    return lit_weighted(p[0].sample.t, p[1].sample.t, table.blend(spot, lighting.weighted[0]),
                        table.blend(spot, lighting.weighted[1]));
  else
    return lit_lagrange(std::array{p[0].sample.t, p[1].sample.t, p[2].sample.t},
                        table.blend(spot, lighting.weighted[0]), table.blend(spot, lighting.weighted[1]),
                        table.blend(spot, lighting.weighted[2]));
}

// The partial last slab of a float march, from the front sample s_front (the
// first sample of slab `full`) to the exit iv.t1, integrated exactly as on
// the double path: Steps linear sub-slabs of equal length, lit as on the
// double path: by the mean of the gradients at their ends (`sampled`) or
// with their exactly weighted integrals (`interpolated`, exact_weighted_slab,
// first order for both orders). Each sub-slab's premultiplied (r, g, b,
// alpha), front to back; all zero when the ray ends on a whole slab. Unlit,
// the exact integral as it is, in double; lit, the float shading's. A
// sub-slab whose scalars `zero` (when given) finds in a zero-opacity range is
// zero without integrating it: most rays leave the volume through empty
// space, and the exact integral walks every table bin between the scalars.
// The GPU backend composites the same values, in float
// (src/methods/march/ray_setup.cpp).
template <int Steps, class Value>
std::array<SlabRgba, Steps> last_slabs(const FloatSampler& sampler, const Value* values, const DiscreteTf& tf,
                                     const FloatLighting& lighting, const Ray& ray, const Interval& iv,
                                     long long full, double h, FloatSample front,
                                     const ZeroOpacity* zero = nullptr) {
  std::array<SlabRgba, Steps> out{};
  const double t_rest = iv.t0 + full * Steps * h;
  const double sub = (iv.t1 - t_rest) / Steps;
  if (!(sub > 0)) return out;
  const FloatShading::Vector d = direction(ray);
  for (int i = 1; i <= Steps; ++i) {
    const FloatSample back =
        sample_at(sampler, values, lighting, d, sampler.grid(ray.at(i == Steps ? iv.t1 : t_rest + i * sub)));
    const auto float4 = [](const SlabRgba& e) {
      return Float4{static_cast<float>(e.r), static_cast<float>(e.g), static_cast<float>(e.b),
                    static_cast<float>(e.a)};
    };
    const auto slab = [](const Float4& v) { return SlabRgba{v[0], v[1], v[2], v[3]}; };
    SlabRgba& v = out[i - 1];
    if (zero && zero->over(std::min(front.s, back.s), std::max(front.s, back.s))) {
      v = SlabRgba{};
    } else if (lighting.interpolated()) {
      const SlabWeights w = exact_weighted_slab(tf, front.s, back.s, sub);
      v = slab(lit_weighted(front.t, back.t, float4(w.front), float4(w.back)));
    } else if (lighting.shading) {
      v = slab(lit_by(lighting.shading->terms(mean(std::array{front.g, back.g}), d),
                      float4(exact_slab(tf, front.s, back.s, sub))));
    } else {
      v = exact_slab(tf, front.s, back.s, sub);
    }
    front = back;
  }
  return out;
}

// The end of a float march: the pixel (C, 1 - T) once T < termination, else
// with the partial last slab (last_slabs) composited. `values`: the volume's
// typed samples (GridVolume::visit).
template <int Steps, class Value>
Rgba finish_float(const FloatSampler& sampler, const Value* values, const DiscreteTf& tf,
                  const FloatLighting& lighting, const Ray& ray, const Interval& iv, long long full, double h,
                  FloatSample front, const Leap& leap, FrontToBack acc) {
  if (!(acc.T < leap.termination))
    for (const SlabRgba& v : last_slabs<Steps>(sampler, values, tf, lighting, ray, iv, full, h, front, leap.zero))
      acc.add(v.r, v.g, v.b, v.a);
  return acc.result();
}

template <class Lookup, class Value>
Rgba march_float(const GridVolume& volume, const FloatSampler& sampler, const Value* values, const Lookup& table,
                 const DiscreteTf& tf, const FloatLighting& lighting, const Ray& ray, double h, const Leap& leap) {
  constexpr int steps = Lookup::kSteps;
  const auto iv = volume.clip(ray);
  if (!iv) return {0, 0, 0, 0};
  const long long all = static_cast<long long>(std::floor(iv->length() / (steps * h)));
  // The owned slabs (a brick's, else all): full ones begin .. full - 1, and
  // the partial slab (piece `all`) where end passes all.
  const PieceRange owned = owned_pieces(*iv, steps * h, all + 1);
  const long long full = std::min(owned.end, all);
  const Vec3 u0 = sampler.grid(ray.at(iv->t0)), du = sampler.grid_step(ray.dir * h);
  struct Point {
    FloatSample sample;
    typename Lookup::Place place;
  };
  using Slab = std::array<Point, steps + 1>;  // the slab's samples, front to back
  const FloatShading::Vector d = direction(ray);
  const auto sample = [&](long long i) {
    const FloatSample s = sample_at(sampler, values, lighting, d, u0 + static_cast<double>(i) * du);
    return Point{s, table.place(s.s)};
  };
  // Samples 1 .. steps of slab k into p (p[0] is in hand).
  const auto fill = [&](Slab& p, long long k) {
    for (int i = 1; i <= steps; ++i) p[i] = sample(k * steps + i);
  };
  const auto find = [&](const Slab& p) {
    std::array<typename Lookup::Place, steps + 1> places;
    for (int i = 0; i <= steps; ++i) places[i] = p[i].place;
    return table.find(places);
  };
  FrontToBack acc;
  // Slab k's samples are in hand and its table spot found; slab k + 1's
  // samples are taken and its spot found (its entries start loading) before
  // slab k is composited.
  Slab p{};
  p[0] = sample(owned.begin * steps);
  if (owned.begin < full) fill(p, owned.begin);
  auto spot = find(p);
  MacroRuns runs(leap.space, ray, iv->t1);
  for (long long k = owned.begin; k < full;) {
    if (const long long j = leap_target(runs, *iv, h, steps, k, full); j > k) {
      k = j;
      p[0] = sample(k * steps);
      if (k == full) break;
      fill(p, k);
      spot = find(p);
    }
    // Slabs k .. stop - 1 start before the end of the run found, where the
    // next leap query is due (all of them without skipping): they need no query.
    const long long stop =
        leap.space ? std::clamp(static_cast<long long>(std::ceil((runs.end() - iv->t0) / (steps * h))), k + 1, full)
                   : full;
    for (; k < stop; ++k) {
      if (acc.T < leap.termination) return acc.result();
      // Past the last full slab the back sample stands in for the next slab's.
      Slab next;
      next.fill(p[steps]);
      if (k + 1 < full) fill(next, k + 1);
      const auto following = find(next);
      const Float4 v = slab_colour(table, spot, p, lighting, d);
      acc.add(v[0], v[1], v[2], v[3]);
      p = next;
      spot = following;
    }
  }
  if (!(owned.begin <= all && all < owned.end)) return acc.result();  // the partial slab is another brick's
  return finish_float<steps>(sampler, values, tf, lighting, ray, *iv, full, h, p[0].sample, leap, acc);
}

}  // namespace vri::detail
