#pragma once
// BoundaryBvh: a bounding-volume hierarchy over the boundary faces of a
// TetMesh (faces with no neighbour), for finding where a ray enters the
// medium - the first time and again after each exit from a non-convex mesh.
#include <cstdint>
#include <optional>
#include <vector>

#include "vri/memory.hpp"
#include "vri/geometry.hpp"
#include "vri/volume.hpp"

namespace vri {

class BoundaryBvh {
 public:
  explicit BoundaryBvh(const TetMesh& mesh);

  struct Hit {
    double t;
    std::int32_t tet;
    int face;
  };
  // The nearest boundary face that faces the ray (the ray enters the mesh
  // through it) hit at t >= t_min and t > t_after, other than face `skip`
  // (4 * tet + face, or -1). Ties in t go to the lower face slot, so the
  // answer never depends on the tree's shape.
  std::optional<Hit> next_entry(const Ray& ray, double t_min, double t_after, std::int64_t skip) const;

  std::size_t face_count() const { return faces_.size(); }

  // The tree as it is, for a device that walks it itself (the Vulkan
  // tet-raycast: vulkan/host/gpu_tet_mesh.hpp); node 0 is the root.
  struct Face {
    Vec3 a, e1, e2;  // a, b - a, c - a with (b-a) x (c-a) pointing out of the mesh
    std::int32_t slot;
  };
  struct Node {
    Vec3 lo, hi;
    std::int32_t first, count;  // leaf: faces_[first, first+count); inner: count = 0, children first, first+1
  };
  const std::vector<Face>& faces() const { return faces_; }
  const std::vector<Node>& nodes() const { return nodes_; }

 private:
  MemoryCharge charge_;  // faces_ and nodes_, held against the process's budget
  std::vector<Face> faces_;
  std::vector<Node> nodes_;
  void build(std::int32_t node, std::int32_t first, std::int32_t count);
};

}  // namespace vri
