#include "mesh/tet_walk.hpp"

#include <limits>
#include <string>

namespace vri {

TetWalk::TetWalk(const TetMesh& mesh)
    : mesh_(mesh),
      charge_(mesh.size(), 4 * sizeof(Plane) + sizeof(Linear),
              "the face planes and linear fields of " + std::to_string(mesh.size()) + " tetrahedra"),
      bvh_(mesh) {
  const auto& p = mesh.points();
  const auto& sc = mesh.scalars();
  planes_.resize(4 * mesh.size());
  fields_.resize(mesh.size());
  for (std::size_t t = 0; t < mesh.size(); ++t) {
    for (int f = 0; f < 4; ++f) {
      const auto v = mesh.face(t, f);
      const Vec3 n = cross(p[v[1]] - p[v[0]], p[v[2]] - p[v[0]]);
      planes_[4 * t + f] = {n, dot(n, p[v[0]])};
    }
    // grad s = sum_k (s_k - s_a) * (cross of the other two edges) / det.
    const auto& v = mesh.tets()[t];
    const Vec3 a = p[v[0]], e1 = p[v[1]] - a, e2 = p[v[2]] - a, e3 = p[v[3]] - a;
    const double sa = sc[v[0]];
    const double det = dot(e1, cross(e2, e3));
    const Vec3 g = ((sc[v[1]] - sa) * cross(e2, e3) + (sc[v[2]] - sa) * cross(e3, e1) +
                    (sc[v[3]] - sa) * cross(e1, e2)) *
                   (1 / det);
    const auto [lo, hi] = std::minmax({sc[v[0]], sc[v[1]], sc[v[2]], sc[v[3]]});
    fields_[t] = {g, sa - dot(g, a), lo, hi};
  }
}

std::pair<double, int> TetWalk::exit_of(std::int32_t tet, int entry_face, const Ray& ray) const {
  double best = std::numeric_limits<double>::infinity();
  int face = -1;
  double steepest = -std::numeric_limits<double>::infinity();
  int steepest_face = 0;
  for (int f = 0; f < 4; ++f) {
    if (f == entry_face) continue;
    const Plane& pl = planes_[4 * tet + f];
    const double dn = dot(pl.normal, ray.dir);
    if (dn > steepest) {
      steepest = dn;
      steepest_face = f;
    }
    if (!(dn > 0)) continue;
    const double t = (pl.offset - dot(pl.normal, ray.origin)) / dn;
    if (t < best) {
      best = t;
      face = f;
    }
  }
  // A ray lying in the planes of all other faces cannot happen in a
  // non-degenerate tetrahedron; guard anyway with a zero-length step.
  if (face < 0) return {-std::numeric_limits<double>::infinity(), steepest_face};
  return {best, face};
}

int TetWalk::face_towards(std::int32_t tet, std::int32_t other) const {
  for (int f = 0; f < 4; ++f)
    if (mesh_.neighbor(tet, f) == other) return f;
  return -1;
}

}  // namespace vri
