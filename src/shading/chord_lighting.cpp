#include "shading/chord_lighting.hpp"

#include "shading/lit_slab.hpp"

namespace vri {

ChordLighting::ChordLighting(const TetMesh& mesh, const Lighting& lighting)
    : gradients_(mesh), shader_(lighting, gradients_.flat_threshold()), interpolated_(lighting.mode == "interpolated") {}

Rgba ChordLighting::sampled(const Rgba& v, std::int32_t tet, Vec3 front, Vec3 back, Vec3 dir) const {
  return lit_by(shader_.terms(0.5 * (gradients_.sample(tet, front) + gradients_.sample(tet, back)), dir), v);
}

Rgba ChordLighting::weighted(const Rgba& front_w, const Rgba& back_w, std::int32_t tet, Vec3 front, Vec3 back,
                             Vec3 dir) const {
  // Lum et al. §3: the terms at the chord's two ends, linear between them.
  return lit_weighted(shader_.terms(gradients_.sample(tet, front), dir),
                      shader_.terms(gradients_.sample(tet, back), dir), front_w, back_w);
}

}  // namespace vri
