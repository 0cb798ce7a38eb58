#pragma once
// What one preint1 slab contributes, per lighting mode (SPEC §5, §9): the
// integrator walks the samples and asks its policy for
//   State at(p)                          what a sample carries (nothing, a gradient, shader terms)
//   Rgba slab(f, b, s_f, s_b)            a whole slab of the table's length
//   Rgba last(f, b, s_f, s_b, length)    the partial last slab, exactly (exact_slab)
// Each sample's state is computed once and serves the slabs on both sides.
#include "vri/core/rgba.hpp"
#include "vri/shading/headlight_shader.hpp"
#include "vri/tables/preintegration_table.hpp"
#include "vri/tables/slab_integral.hpp"
#include "vri/tables/weighted_tables.hpp"

namespace vri::preint1 {

inline Rgba rgba(const SlabRgba& v) { return {v.r, v.g, v.b, v.a}; }

// No lighting: the pre-integrated colour as it is (Engel et al. 2001).
struct Unlit {
  const PreintegrationTable& table;
  const DiscreteTf& tf;
  struct State {};
  State at(Vec3) const { return {}; }
  Rgba slab(State, State, double s_f, double s_b) const { return table.lookup(s_f, s_b); }
  Rgba last(State, State, double s_f, double s_b, double l) const { return rgba(exact_slab(tf, s_f, s_b, l)); }
};

// One normal per slab, from the mean of the gradients at its two samples,
// lighting the pre-integrated colour: C = a C_1 + b alpha_1 (SPEC §5, c_lit = c a + b).
struct Sampled {
  const PreintegrationTable& table;
  const DiscreteTf& tf;
  const HeadlightShader& shader;
  Vec3 dir;
  using State = Vec3;  // the gradient
  State at(Vec3 p) const { return shader.gradients().sample(p); }
  Rgba lit(State f, State b, const Rgba& v) const {
    const auto t = shader.terms(0.5 * (f + b), dir);
    return {v[0] * t.a + t.b * v[3], v[1] * t.a + t.b * v[3], v[2] * t.a + t.b * v[3], v[3]};
  }
  Rgba slab(State f, State b, double s_f, double s_b) const { return lit(f, b, table.lookup(s_f, s_b)); }
  Rgba last(State f, State b, double s_f, double s_b, double l) const {
    return lit(f, b, rgba(exact_slab(tf, s_f, s_b, l)));
  }
};

// Lighting interpolated across the slab (Lum, Wilson & Ma 2004, §3): the
// shader terms at each sample multiply the integrals weighted toward it,
//   C = a_f D_front + b_f S_front + a_b D_back + b_b S_back,   alpha = alpha_1,
// from the packed tables of §5.1 (front = (D_front, alpha), back = (D_back, S_back)).
struct Interpolated {
  const WeightedTables& tables;
  const DiscreteTf& tf;
  const HeadlightShader& shader;
  Vec3 dir;
  using State = HeadlightShader::Terms;
  State at(Vec3 p) const { return shader.at(p, dir); }
  static Rgba lit(State f, State b, const Rgba& front, const Rgba& back) {
    const double specular = f.b * (front[3] - back[3]) + b.b * back[3];
    return {f.a * front[0] + b.a * back[0] + specular, f.a * front[1] + b.a * back[1] + specular,
            f.a * front[2] + b.a * back[2] + specular, front[3]};
  }
  Rgba slab(State f, State b, double s_f, double s_b) const {
    return lit(f, b, tables.front.lookup(s_f, s_b), tables.back.lookup(s_f, s_b));
  }
  Rgba last(State f, State b, double s_f, double s_b, double l) const {
    const SlabWeights w = exact_weighted_slab(tf, s_f, s_b, l);
    return lit(f, b, rgba(w.front), rgba(w.back));
  }
};

}  // namespace vri::preint1
