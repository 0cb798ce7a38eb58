#include "vri/volume.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "vri/error.hpp"

namespace vri {

namespace {

// Vertices of face f listed so that the normal points away from vertex f when
// the tetrahedron is positively oriented (det[b-a, c-a, d-a] > 0).
constexpr int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

double det3(Vec3 a, Vec3 b, Vec3 c) { return dot(a, cross(b, c)); }

}  // namespace

TetMesh::TetMesh(std::vector<Vec3> points, std::vector<Tet> tets, std::vector<float> scalars)
    : points_(std::move(points)), scalars_(std::move(scalars)) {
  const std::size_t np = points_.size();
  if (np > std::size_t{INT32_MAX}) throw Error("mesh has too many points");
  if (scalars_.size() != np)
    throw Error("mesh has " + std::to_string(np) + " points but " + std::to_string(scalars_.size()) +
                " scalars");
  if (tets.empty()) throw Error("mesh has no tetrahedra");
  // Before anything is built: the kept copy of the tetrahedra and their neighbours.
  charge_ = MemoryCharge(bytes_for(np, tets.size()), "a mesh of " + std::to_string(tets.size()) + " tetrahedra");
  for (std::size_t i = 0; i < np; ++i) {
    const Vec3 p = points_[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw Error("mesh point " + std::to_string(i) + " has a non-finite coordinate");
    if (!std::isfinite(scalars_[i]))
      throw Error("mesh point " + std::to_string(i) + " has a non-finite scalar (NaN or inf)");
  }
  tets_.reserve(tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t) {
    Tet v = tets[t];
    for (int k = 0; k < 4; ++k)
      if (v[k] < 0 || std::size_t(v[k]) >= np)
        throw Error("tetrahedron " + std::to_string(t) + " refers to point " + std::to_string(v[k]) +
                    " (the mesh has " + std::to_string(np) + " points)");
    const Vec3 a = points_[v[0]];
    const double vol = det3(points_[v[1]] - a, points_[v[2]] - a, points_[v[3]] - a);
    double longest = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) longest = std::max(longest, length(points_[v[i]] - points_[v[j]]));
    if (!(std::abs(vol) > 1e-12 * longest * longest * longest)) {
      ++dropped_;
      continue;
    }
    if (vol < 0) std::swap(v[2], v[3]);
    tets_.push_back(v);
  }
  if (tets_.empty()) throw Error("mesh has only degenerate tetrahedra");

  // Face adjacency: sort the 4n faces by their sorted vertex triple; equal
  // neighbours in the order are the two sides of one shared face.
  struct FaceKey {
    std::array<std::int32_t, 3> v;
    std::int32_t slot;  // 4 * tet + face
  };
  std::vector<FaceKey> faces;
  faces.reserve(4 * tets_.size());
  for (std::size_t t = 0; t < tets_.size(); ++t)
    for (int f = 0; f < 4; ++f) {
      std::array<std::int32_t, 3> v = {tets_[t][kFace[f][0]], tets_[t][kFace[f][1]], tets_[t][kFace[f][2]]};
      std::sort(v.begin(), v.end());
      faces.push_back({v, static_cast<std::int32_t>(4 * t + f)});
    }
  std::sort(faces.begin(), faces.end(),
            [](const FaceKey& a, const FaceKey& b) { return a.v != b.v ? a.v < b.v : a.slot < b.slot; });
  neighbors_.assign(4 * tets_.size(), -1);
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].v == faces[i].v) ++j;
    if (j - i > 2)
      throw Error("mesh face (" + std::to_string(faces[i].v[0]) + ", " + std::to_string(faces[i].v[1]) +
                  ", " + std::to_string(faces[i].v[2]) + ") is shared by " + std::to_string(j - i) +
                  " tetrahedra (at most 2 allowed)");
    if (j - i == 2) {
      neighbors_[faces[i].slot] = faces[i + 1].slot / 4;
      neighbors_[faces[i + 1].slot] = faces[i].slot / 4;
    }
    i = j;
  }

  // Bounds and scalar range over the points the tetrahedra use; edge lengths
  // over distinct edges (each counted once).
  constexpr double inf = INFINITY;
  lo_ = {inf, inf, inf};
  hi_ = {-inf, -inf, -inf};
  min_ = INFINITY;
  max_ = -INFINITY;
  std::vector<std::pair<std::int32_t, std::int32_t>> edges;
  edges.reserve(6 * tets_.size());
  for (const Tet& v : tets_)
    for (int i = 0; i < 4; ++i) {
      const Vec3 p = points_[v[i]];
      for (int a = 0; a < 3; ++a) {
        lo_[a] = std::min(lo_[a], p[a]);
        hi_[a] = std::max(hi_[a], p[a]);
      }
      min_ = std::min(min_, scalars_[v[i]]);
      max_ = std::max(max_, scalars_[v[i]]);
      for (int j = i + 1; j < 4; ++j) edges.emplace_back(std::min(v[i], v[j]), std::max(v[i], v[j]));
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  double sum = 0;
  for (const auto& [a, b] : edges) {
    const double l = length(points_[a] - points_[b]);
    sum += l;
    max_edge_ = std::max(max_edge_, l);
  }
  mean_edge_ = sum / edges.size();
}

std::array<std::int32_t, 3> TetMesh::face(std::size_t tet, int f) const {
  const Tet& v = tets_[tet];
  return {v[kFace[f][0]], v[kFace[f][1]], v[kFace[f][2]]};
}

}  // namespace vri
