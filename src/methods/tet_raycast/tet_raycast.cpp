#include "tet_raycast.hpp"

#include "methods/mesh_tables.hpp"
#include "vri/error.hpp"

namespace vri {

TetRaycastIntegrator::TetRaycastIntegrator(const TetMesh& mesh, std::unique_ptr<const SlabTable> table,
                                           const Lighting& lighting, std::unique_ptr<const WeightedLengthTables> weighted)
    : walk_(mesh), table_(std::move(table)), weighted_(std::move(weighted)) {
  if (!table_ || table_->max_length() < mesh.max_edge_length() ||
      (weighted_ && weighted_->front.max_length() < mesh.max_edge_length()))
    throw Error("tet-raycast: the table must cover segments up to the longest edge of the mesh");
  if (!lighting.enabled) return;
  lighting_.emplace(mesh, lighting);
  if (lighting_->interpolated() && !weighted_)
    throw Error("tet-raycast: lighting mode 'interpolated' needs the weighted tables");
}

Rgba TetRaycastIntegrator::integrate(const Ray& ray) const {
  double T = 1, C[3] = {0, 0, 0};
  walk_.for_each_segment(ray, [&](const TetSegment& seg) {
    const double l = seg.tb - seg.ta;
    const auto look = [&](ChordTable t) {
      const SlabTable& from = t == ChordTable::plain   ? *table_
                              : t == ChordTable::front ? weighted_->front
                                                       : weighted_->back;
      return from.lookup(l, seg.s_front, seg.s_back);
    };
    const Rgba v = lighting_ ? lighting_->chord(look, seg.tet, ray.at(seg.ta), ray.at(seg.tb), ray.dir)
                             : look(ChordTable::plain);
    for (int c = 0; c < 3; ++c) C[c] += T * v[c];
    T *= 1 - v[3];
    return T > 1e-7;
  });
  return {C[0], C[1], C[2], 1 - T};
}

std::unique_ptr<Integrator> make_tet_raycast(const MethodSpec& spec, const TetMesh& mesh, const TransferFunction& tf,
                                             const Lighting& lighting) {
  return std::make_unique<TetRaycastIntegrator>(mesh, make_slab_table(spec, mesh, tf), lighting,
                                                make_weighted_length_tables(spec, mesh, tf, lighting));
}

}  // namespace vri
