#pragma once
// What one preint1 slab contributes, per lighting mode (SPEC §5, §9): the
// policies of march_uniform_slabs<2> (ray_steps.hpp), which walks the samples
// and asks for
//   State at(p)               what a sample carries (nothing, a gradient, shader terms)
//   Rgba slab({f, b})         a whole slab of the table's length
//   Rgba last(f, b, length)   the partial last slab, exactly (exact_slab)
// The lit partial slab (sampled_last, interpolated_last) and the one-normal
// lighting (lit_by) serve preint2's policies too (preint2_slabs.hpp).
#include <array>

#include "ray_steps.hpp"
#include "vri/core/rgba.hpp"
#include "vri/shading/headlight_shader.hpp"
#include "vri/tables/preintegration_table.hpp"
#include "vri/tables/slab_integral.hpp"
#include "vri/tables/weighted_tables.hpp"

namespace vri::preint1 {

inline Rgba rgba(const SlabRgba& v) { return {v.r, v.g, v.b, v.a}; }

// A pre-integrated slab lit by one normal's terms: C = a C_1 + b alpha_1
// (SPEC §5, c_lit = c a + b; Engel et al. 2001).
inline Rgba lit_by(const HeadlightShader::Terms& t, const Rgba& v) {
  return {v[0] * t.a + t.b * v[3], v[1] * t.a + t.b * v[3], v[2] * t.a + t.b * v[3], v[3]};
}

// A partial slab from s_f to s_b lit by the mean of the gradients at its ends.
inline Rgba sampled_last(const DiscreteTf& tf, const HeadlightShader& shader, Vec3 dir,
                         const detail::SlabSample<Vec3>& f, const detail::SlabSample<Vec3>& b, double l) {
  return lit_by(shader.terms(0.5 * (f.state + b.state), dir), rgba(exact_slab(tf, f.s, b.s, l)));
}

// Interpolated lighting from the weighted integrals, packed as the tables
// (front = (D_front, alpha), back = (D_back, S_back)):
//   C = a_f D_front + b_f S_front + a_b D_back + b_b S_back,   alpha = alpha_1.
inline Rgba lit_weighted(HeadlightShader::Terms f, HeadlightShader::Terms b, const Rgba& front, const Rgba& back) {
  const double specular = f.b * (front[3] - back[3]) + b.b * back[3];
  return {f.a * front[0] + b.a * back[0] + specular, f.a * front[1] + b.a * back[1] + specular,
          f.a * front[2] + b.a * back[2] + specular, front[3]};
}

// A partial slab with interpolated lighting (exact_weighted_slab).
inline Rgba interpolated_last(const DiscreteTf& tf, const detail::SlabSample<HeadlightShader::Terms>& f,
                              const detail::SlabSample<HeadlightShader::Terms>& b, double l) {
  const SlabWeights w = exact_weighted_slab(tf, f.s, b.s, l);
  return lit_weighted(f.state, b.state, rgba(w.front), rgba(w.back));
}

// No lighting: the pre-integrated colour as it is (Engel et al. 2001).
struct Unlit {
  const PreintegrationTable& table;
  const DiscreteTf& tf;
  struct State {};
  using Sample = detail::SlabSample<State>;
  State at(Vec3) const { return {}; }
  Rgba slab(const std::array<Sample, 2>& s) const { return table.lookup(s[0].s, s[1].s); }
  Rgba last(const Sample& f, const Sample& b, double l) const { return rgba(exact_slab(tf, f.s, b.s, l)); }
};

// One normal per slab, from the mean of the gradients at its two samples,
// lighting the pre-integrated colour.
struct Sampled {
  const PreintegrationTable& table;
  const DiscreteTf& tf;
  const HeadlightShader& shader;
  Vec3 dir;
  using Sample = detail::SlabSample<Vec3>;  // the gradient
  Vec3 at(Vec3 p) const { return shader.gradients().sample(p); }
  Rgba slab(const std::array<Sample, 2>& s) const {
    return lit_by(shader.terms(0.5 * (s[0].state + s[1].state), dir), table.lookup(s[0].s, s[1].s));
  }
  Rgba last(const Sample& f, const Sample& b, double l) const { return sampled_last(tf, shader, dir, f, b, l); }
};

// Lighting interpolated across the slab (Lum, Wilson & Ma 2004, §3): the
// shader terms at each sample multiply the integrals weighted toward it, from
// the packed tables of §5.1.
struct Interpolated {
  const WeightedTables& tables;
  const DiscreteTf& tf;
  const HeadlightShader& shader;
  Vec3 dir;
  using Sample = detail::SlabSample<HeadlightShader::Terms>;
  HeadlightShader::Terms at(Vec3 p) const { return shader.at(p, dir); }
  Rgba slab(const std::array<Sample, 2>& s) const {
    return lit_weighted(s[0].state, s[1].state, tables.front.lookup(s[0].s, s[1].s),
                        tables.back.lookup(s[0].s, s[1].s));
  }
  Rgba last(const Sample& f, const Sample& b, double l) const { return interpolated_last(tf, f, b, l); }
};

}  // namespace vri::preint1
