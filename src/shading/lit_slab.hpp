#pragma once
// A pre-integrated slab lit with the headlight shader's terms (SPEC §5,
// c_lit = c a + b; HeadlightShader::Terms), shared by the grid methods'
// slab policies (src/methods/preint/slab_policies.hpp), their float paths
// (src/methods/preint/float_march.hpp) and the mesh methods' chords
// (chord_lighting.hpp). Each works in the precision of its arguments: Terms
// with members a and b, V an RGBA of 4 elements (Rgba in double, Float4 in
// float), the same operations in the same order for both.
#include <array>

#include "vri/geometry.hpp"
#include "shading/headlight_shader.hpp"

namespace vri {

// One normal's terms for the whole slab: C = a C + b alpha (Engel et al. 2001).
template <class Terms, class V>
V lit_by(const Terms& t, const V& v) {
  V out = v;
  for (int c = 0; c < 3; ++c) out[c] = v[c] * t.a + t.b * v[3];
  return out;
}

// First-order interpolated lighting (Lum, Wilson & Ma 2004, §3), the terms
// f at the front and b at the back of the slab, from the packed tables of
// their §5.1 (weighted_tables.hpp: front = (D_front, alpha), back = (D_back, S_back)):
//   C = a_f D_front + b_f S_front + a_b D_back + b_b S_back,   alpha = alpha_1.
template <class Terms, class V>
V lit_weighted(const Terms& f, const Terms& b, const V& front, const V& back) {
  const auto specular = f.b * (front[3] - back[3]) + b.b * back[3];
  V out = front;
  for (int c = 0; c < 3; ++c) out[c] = f.a * front[c] + b.a * back[c] + specular;
  return out;
}

// Second-order interpolated lighting (El Hajjar et al. 2008 with Lum et al.'s
// weighting; docs/LIGHTING.md §6) from the packed weighted tables
// (second_order_weighted.hpp): full = (C, alpha), middle = (D_m, S_m),
// back = (D_b, S_b), D_f = C - D_m - D_b, S_f = alpha - S_m - S_b;
//   C_lit = sum_k a_k D_k + b_k S_k  (k = f, m, b),   alpha = alpha.
template <class Terms, class V>
V lit_lagrange(const std::array<Terms, 3>& t, const V& full, const V& middle, const V& back) {
  const auto s_f = full[3] - middle[3] - back[3];
  const auto specular = t[0].b * s_f + t[1].b * middle[3] + t[2].b * back[3];
  V out = full;
  for (int c = 0; c < 3; ++c) {
    const auto d_f = full[c] - middle[c] - back[c];
    out[c] = t[0].a * d_f + t[1].a * middle[c] + t[2].a * back[c] + specular;
  }
  return out;
}

}  // namespace vri
