#pragma once
// What one pre-integrated slab contributes, per lighting mode (SPEC §5, §9):
// the policies of march_uniform_slabs<Samples> (ray_steps.hpp), the same for
// first order (preint1, Samples = 2, a PreintegrationTable) and second order
// (preint2, Samples = 3, a SecondOrderTable). The march walks the samples and
// asks for
//   State at(p)              what a sample carries (nothing, a gradient, shader terms)
//   Rgba slab(samples)       a whole slab of the table's length, samples front to back
//   Rgba last(f, b, length)  one linear sub-slab of the partial last slab, exactly (exact_slab)
// preint2-dual lights its cell segments with the same pieces (lit_by,
// mean_gradient, lit_lagrange).
#include <array>
#include <cstddef>
#include <utility>

#include "methods/march/ray_steps.hpp"
#include "vri/geometry.hpp"
#include "shading/headlight_shader.hpp"
#include "shading/lit_slab.hpp"
#include "tables/second_order_weighted.hpp"
#include "tables/slab_integral.hpp"
#include "tables/weighted_tables.hpp"

namespace vri::slabs {

using Terms = HeadlightShader::Terms;
using vri::lit_by;  // lit_slab.hpp, shared with the mesh methods
using vri::lit_weighted;
using vri::lit_lagrange;

inline Rgba rgba(const SlabRgba& v) { return {v.r, v.g, v.b, v.a}; }

// table.lookup(s_0, ..., s_{N-1}) at the samples' scalars.
template <class Table, class Sample, std::size_t N>
Rgba lookup(const Table& table, const std::array<Sample, N>& s) {
  return [&]<std::size_t... i>(std::index_sequence<i...>) { return table.lookup(s[i].s...); }(
             std::make_index_sequence<N>{});
}

// The mean of the samples' gradients: the one normal of `sampled` (front and
// back for preint1; front, middle and back for preint2, docs/LIGHTING.md §6).
template <class Sample, std::size_t N>
Vec3 mean_gradient(const std::array<Sample, N>& s) {
  Vec3 sum = s[0].state;
  for (std::size_t i = 1; i < N; ++i) sum = sum + s[i].state;
  return sum * (1.0 / N);
}

// No lighting: the pre-integrated colour as it is (Engel et al. 2001; El
// Hajjar et al. 2008).
template <int Samples, class Table>
struct Unlit {
  const Table& table;
  const DiscreteTf& tf;
  struct State {};
  using Sample = detail::SlabSample<State>;
  State at(Vec3) const { return {}; }
  Rgba slab(const std::array<Sample, Samples>& s) const { return lookup(table, s); }
  Rgba last(const Sample& f, const Sample& b, double l) const { return rgba(exact_slab(tf, f.s, b.s, l)); }
};

// One normal per slab, the mean of its samples' gradients, lighting the
// pre-integrated colour; the partial slab's sub-slabs lit by the mean of the
// gradients at their ends.
template <int Samples, class Table>
struct Sampled {
  const Table& table;
  const DiscreteTf& tf;
  const HeadlightShader& shader;
  Vec3 dir;
  using Sample = detail::SlabSample<Vec3>;  // the gradient
  Vec3 at(Vec3 p) const { return shader.gradients().sample(p); }
  Rgba slab(const std::array<Sample, Samples>& s) const {
    return lit_by(shader.terms(mean_gradient(s), dir), lookup(table, s));
  }
  Rgba last(const Sample& f, const Sample& b, double l) const {
    return lit_by(shader.terms(mean_gradient(std::array{f, b}), dir), rgba(exact_slab(tf, f.s, b.s, l)));
  }
};

// The shader terms at each sample multiply the integrals weighted toward it;
// the partial slab's linear sub-slabs use exact_weighted_slab (first order).
struct InterpolatedBase {
  const DiscreteTf& tf;
  const HeadlightShader& shader;
  Vec3 dir;
  using Sample = detail::SlabSample<Terms>;
  Terms at(Vec3 p) const { return shader.at(p, dir); }
  Rgba last(const Sample& f, const Sample& b, double l) const {
    const SlabWeights w = exact_weighted_slab(tf, f.s, b.s, l);
    return lit_weighted(f.state, b.state, rgba(w.front), rgba(w.back));
  }
};

// preint1: the shading linear across the slab (Lum, Wilson & Ma 2004).
struct Interpolated1 : InterpolatedBase {
  const WeightedTables& tables;
  Rgba slab(const std::array<Sample, 2>& s) const {
    return lit_weighted(s[0].state, s[1].state, lookup(tables.front, s), lookup(tables.back, s));
  }
};

// preint2: the shading quadratic through the three samples (Lagrange weights).
struct Interpolated2 : InterpolatedBase {
  const SecondOrderWeightedTables& tables;
  Rgba slab(const std::array<Sample, 3>& s) const {
    return lit_lagrange(std::array{s[0].state, s[1].state, s[2].state}, lookup(tables.full, s),
                        lookup(tables.middle, s), lookup(tables.back, s));
  }
};

}  // namespace vri::slabs
