#pragma once
// TetWalk: ray casting cell to cell through a TetMesh (Garrity 1990; the
// traversal of Weiler et al. 2003 on the CPU). A ray enters the medium through
// a boundary face found with the BoundaryBvh, leaves each tetrahedron through
// the face whose plane it crosses first, steps to the neighbour across that
// face, and on reaching the boundary looks for the next entry further along,
// so non-convex meshes and meshes with holes are entered as often as needed.
// Inside a tetrahedron the field is linear, so each piece is fully described
// by its length and the scalars at its two ends.
//
// The part of a ray before its first entry through a boundary face is not
// seen: an eye inside the medium misses the medium between it and that face.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "vri/memory.hpp"
#include "vri/geometry.hpp"
#include "mesh/boundary_bvh.hpp"
#include "vri/volume.hpp"

namespace vri {

struct TetSegment {
  std::int32_t tet;
  double ta, tb;           // world-distance range along the ray
  double s_front, s_back;  // scalar at ta and at tb
};

class TetWalk {
 public:
  // Keeps a reference to mesh; precomputes face planes, gradients and the BVH.
  explicit TetWalk(const TetMesh& mesh);

  const TetMesh& mesh() const { return mesh_; }

  // Calls visit(const TetSegment&) for every tetrahedron piece of the ray with
  // t >= 0, front to back, trimmed to the mesh's clip region (the scalars at
  // a cut from the tetrahedron's linear field); stops early when visit
  // returns false.
  template <class Visit>
  void for_each_segment(const Ray& ray, Visit&& visit) const {
    double c0 = 0, c1 = std::numeric_limits<double>::infinity();  // the kept part of the ray
    if (mesh_.clip_region().active() && !mesh_.clip_region().cut(ray, c0, c1)) return;
    double t_exit = 0, t_entry = -1;
    std::int64_t skip = -1;
    // Each boundary entry is strictly further than the previous one, so this
    // ends. A face coincident with the one just left (a non-conforming seam)
    // may be hit a rounding error before the exit, hence the slack.
    while (auto hit = bvh_.next_entry(ray, t_exit - 1e-9 * (1 + std::abs(t_exit)), t_entry, skip)) {
      t_entry = hit->t;
      std::int32_t tet = hit->tet;
      int entry_face = hit->face;
      double t = std::max(hit->t, t_exit);
      double s = scalar_at(tet, ray.at(t));
      for (std::size_t steps = 0; steps < mesh_.size(); ++steps) {
        const auto [tb, face] = exit_of(tet, entry_face, ray);
        const double t_out = std::max(tb, t);
        const double s_out = scalar_at(tet, ray.at(t_out));
        if (t >= c1) return;
        if (t_out > t && t_out > c0) {
          const double a = std::max(t, c0), b = std::min(t_out, c1);
          const TetSegment seg{tet, a, b, a == t ? s : scalar_at(tet, ray.at(a)),
                               b == t_out ? s_out : scalar_at(tet, ray.at(b))};
          if (b > a && !visit(seg)) return;
        }
        t = t_out;
        const std::int32_t next = mesh_.neighbor(tet, face);
        if (next < 0) {
          skip = 4 * std::int64_t(tet) + face;
          break;
        }
        entry_face = face_towards(next, tet);
        tet = next;
        s = scalar_at(tet, ray.at(t));
      }
      t_exit = t;
    }
  }

  // The linear field of tetrahedron `tet` at p, clamped to its vertex range.
  double scalar_at(std::int32_t tet, Vec3 p) const {
    const Linear& f = fields_[tet];
    return std::clamp(dot(f.gradient, p) + f.offset, f.lo, f.hi);
  }

  // What the walk precomputes, for a device that walks on its own (the
  // Vulkan tet-raycast: vulkan/host/gpu_tet_mesh.hpp).
  struct Plane {
    Vec3 normal;  // outward, not normalised
    double offset;  // normal . x = offset on the face
  };
  struct Linear {
    Vec3 gradient;
    double offset, lo, hi;
  };
  const Plane& plane(std::int32_t tet, int face) const { return planes_[4 * std::size_t(tet) + face]; }
  const Linear& field(std::int32_t tet) const { return fields_[tet]; }
  const BoundaryBvh& bvh() const { return bvh_; }

 private:
  // Where the ray leaves `tet` (having entered through entry_face, or -1):
  // the nearest crossing of an outward-facing face plane, and that face.
  std::pair<double, int> exit_of(std::int32_t tet, int entry_face, const Ray& ray) const;
  int face_towards(std::int32_t tet, std::int32_t other) const;

  const TetMesh& mesh_;
  MemoryCharge charge_;        // planes_ and fields_, held against the process's budget
  std::vector<Plane> planes_;  // 4 per tetrahedron
  std::vector<Linear> fields_;
  BoundaryBvh bvh_;
};

}  // namespace vri
