#include "mesh/boundary_bvh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace vri {

namespace {

constexpr int kLeafSize = 4;

Vec3 centroid_of(const Vec3& a, const Vec3& e1, const Vec3& e2) { return a + (e1 + e2) * (1.0 / 3.0); }

}  // namespace

BoundaryBvh::BoundaryBvh(const TetMesh& mesh) {
  std::uint64_t boundary = 0;
  for (std::size_t t = 0; t < mesh.size(); ++t)
    for (int f = 0; f < 4; ++f) boundary += mesh.neighbor(t, f) < 0;
  const std::uint64_t node_count = 2 * boundary / kLeafSize + 2;
  charge_ = MemoryCharge(boundary * sizeof(Face) + node_count * sizeof(Node),
                         "the search tree of " + std::to_string(boundary) + " boundary faces");
  faces_.reserve(boundary);
  const auto& p = mesh.points();
  for (std::size_t t = 0; t < mesh.size(); ++t)
    for (int f = 0; f < 4; ++f)
      if (mesh.neighbor(t, f) < 0) {
        const auto v = mesh.face(t, f);
        faces_.push_back({p[v[0]], p[v[1]] - p[v[0]], p[v[2]] - p[v[0]], static_cast<std::int32_t>(4 * t + f)});
      }
  if (faces_.empty()) return;
  nodes_.reserve(node_count);
  nodes_.push_back({});
  build(0, 0, static_cast<std::int32_t>(faces_.size()));
}

void BoundaryBvh::build(std::int32_t node, std::int32_t first, std::int32_t count) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Vec3 lo{inf, inf, inf}, hi{-inf, -inf, -inf}, clo = lo, chi = hi;
  for (std::int32_t i = first; i < first + count; ++i) {
    const Face& f = faces_[i];
    for (const Vec3 q : {f.a, f.a + f.e1, f.a + f.e2})
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], q[a]);
        hi[a] = std::max(hi[a], q[a]);
      }
    const Vec3 c = centroid_of(f.a, f.e1, f.e2);
    for (int a = 0; a < 3; ++a) {
      clo[a] = std::min(clo[a], c[a]);
      chi[a] = std::max(chi[a], c[a]);
    }
  }
  nodes_[node].lo = lo;
  nodes_[node].hi = hi;
  if (count <= kLeafSize) {
    nodes_[node].first = first;
    nodes_[node].count = count;
    return;
  }
  // Median split on the longest axis of the centroids; ties broken by slot so
  // the tree is the same on every platform.
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (chi[a] - clo[a] > chi[axis] - clo[axis]) axis = a;
  const std::int32_t half = count / 2;
  std::nth_element(faces_.begin() + first, faces_.begin() + first + half, faces_.begin() + first + count,
                   [axis](const Face& x, const Face& y) {
                     const double cx = centroid_of(x.a, x.e1, x.e2)[axis], cy = centroid_of(y.a, y.e1, y.e2)[axis];
                     return cx != cy ? cx < cy : x.slot < y.slot;
                   });
  const auto left = static_cast<std::int32_t>(nodes_.size());
  nodes_.push_back({});
  nodes_.push_back({});
  nodes_[node].first = left;
  nodes_[node].count = 0;
  build(left, first, half);
  build(left + 1, first + half, count - half);
}

std::optional<BoundaryBvh::Hit> BoundaryBvh::next_entry(const Ray& ray, double t_min, double t_after,
                                                        std::int64_t skip) const {
  if (nodes_.empty()) return std::nullopt;
  constexpr double inf = std::numeric_limits<double>::infinity();
  const Vec3 inv{1 / ray.dir.x, 1 / ray.dir.y, 1 / ray.dir.z};
  double best_t = inf;
  std::int32_t best_slot = -1;
  std::int32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    // Slab test; a zero direction component gives +-inf or NaN, which the
    // comparisons below treat as "no constraint" or "miss" as appropriate.
    double t0 = t_min, t1 = best_t;
    bool miss = false;
    for (int a = 0; a < 3; ++a) {
      if (ray.dir[a] == 0) {
        if (ray.origin[a] < n.lo[a] || ray.origin[a] > n.hi[a]) miss = true;
        continue;
      }
      double ta = (n.lo[a] - ray.origin[a]) * inv[a], tb = (n.hi[a] - ray.origin[a]) * inv[a];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
    }
    if (miss || t0 > t1 * (1 + 1e-12) + 1e-300) continue;
    if (n.count == 0) {
      stack[top++] = n.first + 1;
      stack[top++] = n.first;
      continue;
    }
    for (std::int32_t i = n.first; i < n.first + n.count; ++i) {
      const Face& f = faces_[i];
      if (f.slot == skip) continue;
      // Moller-Trumbore, facing faces only (the ray goes against the outward normal).
      const Vec3 normal = cross(f.e1, f.e2);
      if (!(dot(normal, ray.dir) < 0)) continue;
      const Vec3 pv = cross(ray.dir, f.e2);
      const double det = dot(f.e1, pv);
      if (det == 0) continue;
      const double inv_det = 1 / det;
      const Vec3 tv = ray.origin - f.a;
      const double u = dot(tv, pv) * inv_det;
      constexpr double eps = 1e-10;  // closes the cracks between neighbouring faces
      if (u < -eps || u > 1 + eps) continue;
      const Vec3 qv = cross(tv, f.e1);
      const double v = dot(ray.dir, qv) * inv_det;
      if (v < -eps || u + v > 1 + eps) continue;
      const double t = dot(f.e2, qv) * inv_det;
      if (t < t_min || !(t > t_after)) continue;
      if (t < best_t || (t == best_t && f.slot < best_slot)) {
        best_t = t;
        best_slot = f.slot;
      }
    }
  }
  if (best_slot < 0) return std::nullopt;
  return Hit{best_t, best_slot / 4, best_slot % 4};
}

}  // namespace vri
