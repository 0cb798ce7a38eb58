#include "vri/shading/chord_lighting.hpp"

#include <string>

#include "vri/core/error.hpp"

namespace vri {

namespace {

const Lighting& sampled_only(const Lighting& l, std::string_view method) {
  if (l.mode != "sampled")
    throw Error(std::string(method) + ": lighting mode '" + l.mode +
                "' is not supported on tetrahedral meshes; use 'sampled'");
  return l;
}

}  // namespace

ChordLighting::ChordLighting(const TetMesh& mesh, const Lighting& lighting, std::string_view method)
    : gradients_(mesh), shader_(sampled_only(lighting, method), gradients_.flat_threshold()) {}

Rgba ChordLighting::apply(const Rgba& v, std::int32_t tet, Vec3 front, Vec3 back, Vec3 dir) const {
  const Vec3 g = 0.5 * (gradients_.sample(tet, front) + gradients_.sample(tet, back));
  const auto t = shader_.terms(g, dir);
  return {v[0] * t.a + t.b * v[3], v[1] * t.a + t.b * v[3], v[2] * t.a + t.b * v[3], v[3]};
}

}  // namespace vri
