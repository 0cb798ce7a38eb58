#pragma once
// ChordLighting (SPEC §5, for tet-raycast, pt and pt-cylindrical): lights the
// pre-integrated chord through one tetrahedron, from entry point `front` to
// exit point `back`. The gradient along the chord is linear (PointGradients),
// so the shading terms (a, b) of c_lit = c a + b are known at both ends.
//  * mode `sampled`: one normal, from the mean of the point gradients at entry
//    and exit (the gradient at the chord's midpoint), lights the plain
//    table's colour as a whole, C_lit = a C + b alpha (Roettger & Ertl 2002
//    look up one normal per segment likewise).
//  * mode `interpolated` (Lum, Wilson & Ma 2004, §3): the terms at entry and
//    exit, (a_f, b_f) and (a_b, b_b), taken linear along the chord, multiply
//    the weighted (l, s_f, s_b) tables (WeightedLengthTables, packed as their
//    §5.1): C = a_f D_front + b_f S_front + a_b D_back + b_b S_back,
//    alpha = alpha_1 (lit_weighted).
// The caller reads the tables (a 3D LengthTable or cylinder planes), so the
// same lighting serves every mesh method.
#include <cstdint>

#include "vri/geometry.hpp"
#include "mesh/point_gradients.hpp"
#include "shading/headlight_shader.hpp"

namespace vri {

// The table a chord is read from: the plain one, or a weighted one.
enum class ChordTable { plain = 0, front = 1, back = 2 };

class ChordLighting {
 public:
  // Keeps a reference to mesh. Throws vri::Error for bad coefficients.
  ChordLighting(const TetMesh& mesh, const Lighting& lighting);

  // Mode interpolated: chords are read from the weighted tables.
  bool interpolated() const { return interpolated_; }

  // The lit chord of tetrahedron `tet` from `front` to `back`, seen along the
  // unit direction dir; look(ChordTable) reads it from one table: the plain
  // table in mode sampled, the front and back weighted tables in mode interpolated.
  template <class Look>
  Rgba chord(Look look, std::int32_t tet, Vec3 front, Vec3 back, Vec3 dir) const {
    return interpolated_ ? weighted(look(ChordTable::front), look(ChordTable::back), tet, front, back, dir)
                         : sampled(look(ChordTable::plain), tet, front, back, dir);
  }

  // Mode sampled: the plain table's (C, alpha) v, lit with one normal.
  Rgba sampled(const Rgba& v, std::int32_t tet, Vec3 front, Vec3 back, Vec3 dir) const;
  // Mode interpolated: the packed weighted tables' values, lit with the terms at both ends.
  Rgba weighted(const Rgba& front_w, const Rgba& back_w, std::int32_t tet, Vec3 front, Vec3 back, Vec3 dir) const;

 private:
  PointGradients gradients_;
  HeadlightShader shader_;
  bool interpolated_;
};

}  // namespace vri
