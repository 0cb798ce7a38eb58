#pragma once
// A pre-integrated slab lit with the headlight shader's terms (SPEC §5,
// c_lit = c a + b; HeadlightShader::Terms), shared by the grid methods'
// slab policies (src/integrators/slab_policies.hpp) and the mesh methods'
// chords (chord_lighting.hpp).
#include "vri/core/rgba.hpp"
#include "vri/shading/headlight_shader.hpp"

namespace vri {

// One normal's terms for the whole slab: C = a C + b alpha (Engel et al. 2001).
inline Rgba lit_by(const HeadlightShader::Terms& t, const Rgba& v) {
  return {v[0] * t.a + t.b * v[3], v[1] * t.a + t.b * v[3], v[2] * t.a + t.b * v[3], v[3]};
}

// First-order interpolated lighting (Lum, Wilson & Ma 2004, §3), the terms
// f at the front and b at the back of the slab, from the packed tables of
// their §5.1 (weighted_tables.hpp: front = (D_front, alpha), back = (D_back, S_back)):
//   C = a_f D_front + b_f S_front + a_b D_back + b_b S_back,   alpha = alpha_1.
inline Rgba lit_weighted(HeadlightShader::Terms f, HeadlightShader::Terms b, const Rgba& front, const Rgba& back) {
  const double specular = f.b * (front[3] - back[3]) + b.b * back[3];
  return {f.a * front[0] + b.a * back[0] + specular, f.a * front[1] + b.a * back[1] + specular,
          f.a * front[2] + b.a * back[2] + specular, front[3]};
}

}  // namespace vri
