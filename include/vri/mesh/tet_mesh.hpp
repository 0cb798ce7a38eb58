#pragma once
// TetMesh (SPEC §2): points with one scalar each and tetrahedra of four point
// indices; the field is linear inside each tetrahedron and the medium is the
// union of the tetrahedra (it may be non-convex and have holes).
//
// Construction checks and normalises the input once, so every consumer can
// rely on it:
//  - a point index out of range, a non-finite coordinate or scalar (NaN
//    included) is refused with vri::Error naming the tetrahedron or point;
//  - inverted tetrahedra (negative signed volume) are reoriented by swapping
//    two vertices, so every kept tetrahedron has det[b-a, c-a, d-a] > 0;
//  - degenerate tetrahedra (|volume| <= 1e-12 * (longest edge)^3: flat or
//    with repeated points) hold no medium and are dropped; dropped() counts them;
//  - a face shared by more than two tetrahedra is refused (not a 3-manifold).
// Face f of a tetrahedron is the one opposite its vertex f; neighbor(t, f) is
// the tetrahedron across it, or -1 on the boundary.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "vri/core/memory_limit.hpp"
#include "vri/core/vec3.hpp"

namespace vri {

class TetMesh {
 public:
  using Tet = std::array<std::int32_t, 4>;

  TetMesh(std::vector<Vec3> points, std::vector<Tet> tets, std::vector<float> scalars);
  // The bytes a mesh of this size holds (and charges to the memory budget).
  static std::uint64_t bytes_for(std::uint64_t points, std::uint64_t tets) {
    return points * (sizeof(Vec3) + sizeof(float)) + tets * (sizeof(Tet) + 4 * sizeof(std::int32_t));
  }

  const std::vector<Vec3>& points() const { return points_; }
  const std::vector<Tet>& tets() const { return tets_; }
  const std::vector<float>& scalars() const { return scalars_; }
  std::size_t size() const { return tets_.size(); }
  std::size_t dropped() const { return dropped_; }

  std::int32_t neighbor(std::size_t tet, int face) const { return neighbors_[4 * tet + face]; }
  // The three vertices of face f (opposite vertex f), ordered so that their
  // normal (b-a) x (c-a) points out of the tetrahedron.
  std::array<std::int32_t, 3> face(std::size_t tet, int face) const;

  Vec3 box_lo() const { return lo_; }
  Vec3 box_hi() const { return hi_; }
  float min_value() const { return min_; }
  float max_value() const { return max_; }
  // Mean length over the distinct edges: the mesh's voxel unit (SPEC §2).
  double mean_edge_length() const { return mean_edge_; }
  // Longest edge: no straight segment inside one tetrahedron is longer.
  double max_edge_length() const { return max_edge_; }

 private:
  std::vector<Vec3> points_;
  std::vector<Tet> tets_;
  std::vector<float> scalars_;
  std::vector<std::int32_t> neighbors_;
  MemoryCharge charge_;  // the arrays above, held against the process's budget
  std::size_t dropped_ = 0;
  Vec3 lo_, hi_;
  float min_ = 0, max_ = 0;
  double mean_edge_ = 0, max_edge_ = 0;
};

}  // namespace vri
