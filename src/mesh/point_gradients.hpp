#pragma once
// PointGradients (SPEC §5 on tetrahedral meshes): the gradient at each point
// is the volume-weighted average of the constant gradients of the
// tetrahedra around it; inside a tetrahedron the four point gradients are
// interpolated linearly (barycentric), so the gradient is linear along a ray
// through it. Computed once per mesh.
#include <array>
#include <cstdint>
#include <vector>

#include "vri/geometry.hpp"
#include "vri/volume.hpp"

namespace vri {

// The constant gradient, on tetrahedron `tet`, of the linear function with
// values v at its four vertices (in the order of mesh.tets()[tet]).
Vec3 tet_gradient(const TetMesh& mesh, std::size_t tet, const std::array<double, 4>& v);

// The gradients of the barycentric coordinates of vertices 1, 2 and 3 of a
// tetrahedron with edges e1, e2, e3 from vertex 0.
std::array<Vec3, 3> barycentric_gradients(Vec3 e1, Vec3 e2, Vec3 e3);

class PointGradients {
 public:
  // Keeps a reference to mesh. A point in no tetrahedron gets gradient 0.
  explicit PointGradients(const TetMesh& mesh);

  Vec3 at_point(std::int32_t point) const { return g_[point]; }
  // The barycentric interpolation of the four point gradients of `tet` at p.
  Vec3 sample(std::int32_t tet, Vec3 p) const;
  // SPEC §5's flat threshold on a mesh: 1e-6 (max - min) per unit length.
  double flat_threshold() const { return flat_threshold(mesh_); }
  static double flat_threshold(const TetMesh& mesh);

 private:
  const TetMesh& mesh_;
  std::vector<Vec3> g_;
};

}  // namespace vri
