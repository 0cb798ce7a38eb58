#pragma once
// ChordLighting (SPEC §5, for tet-raycast and pt; pt-cylindrical in mode
// `sampled` only): lights the pre-integrated chord through one tetrahedron,
// from entry point `front` to exit point `back`. The gradient along the chord
// is linear (PointGradients), so the shading terms (a, b) of c_lit = c a + b
// are known at both ends.
//  * mode `sampled`: one normal, from the mean of the point gradients at entry
//    and exit, lights the table's colour as a whole, C_lit = a C + b alpha
//    (Roettger & Ertl 2002 look up one normal per segment likewise).
//  * mode `interpolated` (Lum, Wilson & Ma 2004, §3): the terms at entry and
//    exit, (a_f, b_f) and (a_b, b_b), taken linear along the chord, multiply
//    the weighted (l, s_f, s_b) tables (WeightedLengthTables, packed as their
//    §5.1): C = a_f D_front + b_f S_front + a_b D_back + b_b S_back,
//    alpha = alpha_1 (lit_weighted). For pt-cylindrical it is refused: its
//    chords are read from cylinder planes resampled from one table, and the
//    weighted tables would need their own pair of resamplings (not done).
#include <cstdint>
#include <string_view>

#include "vri/core/rgba.hpp"
#include "vri/mesh/point_gradients.hpp"
#include "vri/shading/headlight_shader.hpp"
#include "vri/tables/slab_table.hpp"
#include "vri/tables/weighted_tables.hpp"

namespace vri {

class ChordLighting {
 public:
  // Keeps references to mesh and weighted. weighted: the tables of mode
  // `interpolated`, ignored in mode `sampled`. Throws vri::Error naming
  // `method` for mode `interpolated` without tables, and for bad coefficients.
  ChordLighting(const TetMesh& mesh, const Lighting& lighting, std::string_view method,
                const WeightedLengthTables* weighted = nullptr);

  // Would the chord be read from the weighted tables (mode interpolated)?
  bool interpolated() const { return weighted_ != nullptr; }

  // Mode sampled: the pre-integrated (C, alpha) v of the chord of tetrahedron
  // `tet` from `front` to `back`, seen along the unit direction dir, lit.
  Rgba apply(const Rgba& v, std::int32_t tet, Vec3 front, Vec3 back, Vec3 dir) const;

  // The lit chord of length l with scalars s_f, s_b: mode sampled reads
  // `table`, mode interpolated the weighted tables.
  Rgba chord(const SlabTable& table, double l, double s_f, double s_b, std::int32_t tet, Vec3 front, Vec3 back,
             Vec3 dir) const;

 private:
  PointGradients gradients_;
  HeadlightShader shader_;
  const WeightedLengthTables* weighted_;
};

}  // namespace vri
