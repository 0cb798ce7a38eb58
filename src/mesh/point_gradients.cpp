#include "mesh/point_gradients.hpp"

namespace vri {

// det = e1 . (e2 x e3)
std::array<Vec3, 3> barycentric_gradients(Vec3 e1, Vec3 e2, Vec3 e3) {
  const double inv = 1 / dot(e1, cross(e2, e3));
  return {cross(e2, e3) * inv, cross(e3, e1) * inv, cross(e1, e2) * inv};
}

Vec3 tet_gradient(const TetMesh& mesh, std::size_t tet, const std::array<double, 4>& v) {
  const auto& p = mesh.points();
  const auto& t = mesh.tets()[tet];
  const Vec3 a = p[t[0]];
  const auto l = barycentric_gradients(p[t[1]] - a, p[t[2]] - a, p[t[3]] - a);
  return (v[1] - v[0]) * l[0] + (v[2] - v[0]) * l[1] + (v[3] - v[0]) * l[2];
}

PointGradients::PointGradients(const TetMesh& mesh) : mesh_(mesh), g_(mesh.points().size()) {
  const auto& p = mesh.points();
  const auto& sc = mesh.scalars();
  std::vector<double> weight(p.size(), 0.0);
  for (std::size_t t = 0; t < mesh.size(); ++t) {
    const auto& v = mesh.tets()[t];
    const Vec3 g = tet_gradient(mesh, t, {sc[v[0]], sc[v[1]], sc[v[2]], sc[v[3]]});
    const Vec3 a = p[v[0]];
    const double volume = dot(p[v[1]] - a, cross(p[v[2]] - a, p[v[3]] - a)) / 6;  // > 0 (TetMesh orients)
    for (int k = 0; k < 4; ++k) {
      g_[v[k]] = g_[v[k]] + volume * g;
      weight[v[k]] += volume;
    }
  }
  for (std::size_t i = 0; i < g_.size(); ++i)
    if (weight[i] > 0) g_[i] = g_[i] * (1 / weight[i]);
}

Vec3 PointGradients::sample(std::int32_t tet, Vec3 x) const {
  const auto& p = mesh_.points();
  const auto& t = mesh_.tets()[tet];
  const Vec3 a = p[t[0]];
  const auto l = barycentric_gradients(p[t[1]] - a, p[t[2]] - a, p[t[3]] - a);
  const Vec3 g0 = g_[t[0]];
  return g0 + dot(l[0], x - a) * (g_[t[1]] - g0) + dot(l[1], x - a) * (g_[t[2]] - g0) +
         dot(l[2], x - a) * (g_[t[3]] - g0);
}

double PointGradients::flat_threshold(const TetMesh& mesh) {
  return 1e-6 * (double(mesh.max_value()) - mesh.min_value());
}

}  // namespace vri
