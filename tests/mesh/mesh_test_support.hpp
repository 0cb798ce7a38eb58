#pragma once
// Small meshes for the mesh tests.
#include <vector>

#include "vri/volume.hpp"
#include "mesh/tetrahedralize.hpp"
#include "test_support.hpp"

namespace vri::test {

// The unit tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1) with the given scalars.
inline TetMesh unit_tet(std::vector<float> s = {0, 1, 2, 3}) {
  return TetMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 1, 2, 3}}, std::move(s));
}

// A tetrahedralised n^3-point grid on [0, n-1]^3 with f at each point, keeping
// only the tetrahedra whose centroid passes keep(x, y, z).
template <class F, class Keep>
TetMesh carved_mesh(int n, F&& f, Keep&& keep, int per_cell = 5) {
  const TetMesh full = tetrahedralize(volume_from({n, n, n}, f), per_cell);
  std::vector<TetMesh::Tet> kept;
  for (const auto& t : full.tets()) {
    Vec3 c{};
    for (int k = 0; k < 4; ++k) c = c + 0.25 * full.points()[t[k]];
    if (keep(c.x, c.y, c.z)) kept.push_back(t);
  }
  return TetMesh(full.points(), kept, full.scalars());
}

}  // namespace vri::test
