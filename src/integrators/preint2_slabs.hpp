#pragma once
// What one preint2 slab (two steps, front / middle / back sample) contributes,
// per lighting mode (SPEC §5, §9): the policies of march_uniform_slabs<3>
// (ray_steps.hpp). The partial last slab is two linear sub-slabs lit as
// preint1 lights its partial slab (preint1_slabs.hpp).
#include <array>

#include "preint1_slabs.hpp"
#include "ray_steps.hpp"
#include "vri/core/rgba.hpp"
#include "vri/shading/headlight_shader.hpp"
#include "vri/tables/second_order_weighted.hpp"
#include "vri/tables/slab_integral.hpp"

namespace vri::preint2 {

// The mean of the gradients at a slab's front, middle and back sample: the
// one normal of `sampled` (docs/LIGHTING.md, "Second order").
inline Vec3 mean_gradient(Vec3 f, Vec3 m, Vec3 b) { return (f + m + b) * (1.0 / 3.0); }

// Interpolated lighting across a second-order slab from the packed weighted
// tables (second_order_weighted.hpp): full = (C, alpha), middle = (D_m, S_m),
// back = (D_b, S_b), D_f = C - D_m - D_b, S_f = alpha - S_m - S_b;
//   C_lit = sum_k a_k D_k + b_k S_k  (k = f, m, b),   alpha = alpha.
inline Rgba lit_lagrange(const std::array<HeadlightShader::Terms, 3>& t, const Rgba& full, const Rgba& middle,
                         const Rgba& back) {
  const double s_f = full[3] - middle[3] - back[3];
  const double specular = t[0].b * s_f + t[1].b * middle[3] + t[2].b * back[3];
  Rgba out;
  for (int c = 0; c < 3; ++c) {
    const double d_f = full[c] - middle[c] - back[c];
    out[c] = t[0].a * d_f + t[1].a * middle[c] + t[2].a * back[c] + specular;
  }
  out[3] = full[3];
  return out;
}

// No lighting: the second-order pre-integrated colour (El Hajjar et al. 2008).
struct Unlit {
  const SecondOrderTable& table;
  const DiscreteTf& tf;
  struct State {};
  using Sample = detail::SlabSample<State>;
  State at(Vec3) const { return {}; }
  Rgba slab(const std::array<Sample, 3>& s) const { return table.lookup(s[0].s, s[1].s, s[2].s); }
  Rgba last(const Sample& f, const Sample& b, double l) const { return preint1::rgba(exact_slab(tf, f.s, b.s, l)); }
};

// One normal per slab, from the mean of its three samples' gradients, lighting
// the pre-integrated colour (C = a C + b alpha, as preint1's sampled).
struct Sampled {
  const SecondOrderTable& table;
  const DiscreteTf& tf;
  const HeadlightShader& shader;
  Vec3 dir;
  using Sample = detail::SlabSample<Vec3>;  // the gradient
  Vec3 at(Vec3 p) const { return shader.gradients().sample(p); }
  Rgba slab(const std::array<Sample, 3>& s) const {
    return preint1::lit_by(shader.terms(mean_gradient(s[0].state, s[1].state, s[2].state), dir),
                           table.lookup(s[0].s, s[1].s, s[2].s));
  }
  Rgba last(const Sample& f, const Sample& b, double l) const {
    return preint1::sampled_last(tf, shader, dir, f, b, l);
  }
};

// The shading interpolated quadratically through the three samples (Lum,
// Wilson & Ma 2004's interpolated lighting with the Lagrange weights).
struct Interpolated {
  const SecondOrderWeightedTables& tables;
  const DiscreteTf& tf;
  const HeadlightShader& shader;
  Vec3 dir;
  using Sample = detail::SlabSample<HeadlightShader::Terms>;
  HeadlightShader::Terms at(Vec3 p) const { return shader.at(p, dir); }
  Rgba slab(const std::array<Sample, 3>& s) const {
    const auto look = [&](const SecondOrderTable& t) { return t.lookup(s[0].s, s[1].s, s[2].s); };
    return lit_lagrange({s[0].state, s[1].state, s[2].state}, look(tables.full), look(tables.middle),
                        look(tables.back));
  }
  Rgba last(const Sample& f, const Sample& b, double l) const { return preint1::interpolated_last(tf, f, b, l); }
};

}  // namespace vri::preint2
