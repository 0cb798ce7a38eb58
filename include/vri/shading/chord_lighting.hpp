#pragma once
// ChordLighting (SPEC §5, lighting mode `sampled`, for tet-raycast, pt and
// pt-cylindrical): a pre-integrated chord through one tetrahedron gets one
// normal, from the mean of the point gradients (PointGradients) at its entry
// and exit, and the table's colour is lit as a whole, C_lit = a C + b alpha:
// with the terms a, b constant along the chord this is the exact integral
// of c_lit = c a + b (Roettger & Ertl 2002 look up one normal per segment
// likewise). Mode `interpolated` would need weighted tables; on meshes it is
// refused.
#include <cstdint>
#include <string_view>

#include "vri/core/rgba.hpp"
#include "vri/mesh/point_gradients.hpp"
#include "vri/shading/headlight_shader.hpp"

namespace vri {

class ChordLighting {
 public:
  // Keeps a reference to mesh. Throws vri::Error naming `method` for mode
  // `interpolated`, and for bad coefficients.
  ChordLighting(const TetMesh& mesh, const Lighting& lighting, std::string_view method);

  // The pre-integrated (C, alpha) of the chord of tetrahedron `tet` from
  // `front` to `back`, seen along the unit direction dir, lit.
  Rgba apply(const Rgba& v, std::int32_t tet, Vec3 front, Vec3 back, Vec3 dir) const;

 private:
  PointGradients gradients_;
  HeadlightShader shader_;
};

}  // namespace vri
