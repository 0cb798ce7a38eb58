#include "vri/shading/chord_lighting.hpp"

#include <string>

#include "vri/core/error.hpp"
#include "vri/shading/lit_slab.hpp"

namespace vri {

namespace {

const WeightedLengthTables* tables_for(const Lighting& l, std::string_view method,
                                       const WeightedLengthTables* weighted) {
  if (l.mode != "interpolated") return nullptr;
  if (!weighted)
    throw Error(std::string(method) + ": lighting mode 'interpolated' is not supported by this method; use 'sampled'");
  return weighted;
}

}  // namespace

ChordLighting::ChordLighting(const TetMesh& mesh, const Lighting& lighting, std::string_view method,
                             const WeightedLengthTables* weighted)
    : gradients_(mesh), shader_(lighting, gradients_.flat_threshold()),
      weighted_(tables_for(lighting, method, weighted)) {}

Rgba ChordLighting::apply(const Rgba& v, std::int32_t tet, Vec3 front, Vec3 back, Vec3 dir) const {
  return lit_by(shader_.terms(0.5 * (gradients_.sample(tet, front) + gradients_.sample(tet, back)), dir), v);
}

Rgba ChordLighting::chord(const SlabTable& table, double l, double s_f, double s_b, std::int32_t tet, Vec3 front,
                          Vec3 back, Vec3 dir) const {
  if (!weighted_) return apply(table.lookup(l, s_f, s_b), tet, front, back, dir);
  // Lum et al. §3: the terms at the chord's two ends, linear between them.
  return lit_weighted(shader_.terms(gradients_.sample(tet, front), dir), shader_.terms(gradients_.sample(tet, back), dir),
                      weighted_->front.lookup(l, s_f, s_b), weighted_->back.lookup(l, s_f, s_b));
}

}  // namespace vri
