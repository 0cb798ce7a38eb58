#pragma once
// A tetrahedral mesh on the device, as src/methods/tet_raycast/tet_raycast.comp walks it: the
// CPU walk's face planes and linear fields (TetWalk), the neighbours, the
// BoundaryBvh's nodes and faces, and, lit, each tetrahedron's point
// gradients with the barycentric coordinates' gradients (PointGradients) -
// all in float, less the mesh box's centre.
#include <memory>
#include <optional>

#include "gpu_buffer.hpp"
#include "vri/volume.hpp"
#include "mesh/tet_walk.hpp"

namespace vri::vulkan {

struct GpuTetMesh {
  // lit: with the lighting buffer (else it holds one float).
  GpuTetMesh(const std::shared_ptr<const VulkanDevice>& device, const TetMesh& mesh, bool lit);
  Vec3 centre;   // subtracted from every position
  float extent;  // the box's diagonal
  GpuBuffer tets, neighbors, nodes, faces, lighting;

 private:
  GpuTetMesh(const std::shared_ptr<const VulkanDevice>& device, const TetWalk& walk, bool lit);
};

}  // namespace vri::vulkan
