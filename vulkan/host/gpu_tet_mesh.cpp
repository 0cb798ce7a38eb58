#include "gpu_tet_mesh.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "vri/error.hpp"
#include "mesh/boundary_bvh.hpp"
#include "mesh/point_gradients.hpp"
#include "mesh/tet_walk.hpp"

namespace vri::vulkan {

namespace {

template <class T>
std::span<const std::byte> bytes_of(const std::vector<T>& v) {
  return std::as_bytes(std::span<const T>(v));
}

void push(std::vector<float>& out, Vec3 v) {
  for (int a = 0; a < 3; ++a) out.push_back(static_cast<float>(v[a]));
}

std::vector<float> tet_data(const TetWalk& walk, Vec3 c) {
  const std::size_t n = walk.mesh().size();
  std::vector<float> out;
  out.reserve(24 * n);
  for (std::size_t t = 0; t < n; ++t) {
    const auto tet = static_cast<std::int32_t>(t);
    for (int f = 0; f < 4; ++f) {  // n . (x + c) = offset
      const TetWalk::Plane& pl = walk.plane(tet, f);
      push(out, pl.normal);
      out.push_back(static_cast<float>(pl.offset - dot(pl.normal, c)));
    }
    const TetWalk::Linear& f = walk.field(tet);  // g . (x + c) + offset
    push(out, f.gradient);
    out.insert(out.end(), {static_cast<float>(f.offset + dot(f.gradient, c)), static_cast<float>(f.lo),
                           static_cast<float>(f.hi), 0.0f, 0.0f});
  }
  return out;
}

std::vector<float> bvh_nodes(const BoundaryBvh& bvh, Vec3 c, double pad) {
  std::vector<float> out;
  for (const BoundaryBvh::Node& node : bvh.nodes()) {
    // Widened by a rounding's worth, so that float slab tests keep every face.
    push(out, node.lo - c - Vec3{pad, pad, pad});
    push(out, node.hi - c + Vec3{pad, pad, pad});
    out.push_back(std::bit_cast<float>(node.first));
    out.push_back(std::bit_cast<float>(node.count));
  }
  // A finite mesh has a boundary (TetMesh refuses empty ones).
  if (out.empty()) throw Error("tet-raycast: the mesh has no boundary faces");
  return out;
}

std::vector<float> bvh_faces(const BoundaryBvh& bvh, Vec3 c) {
  std::vector<float> out;
  for (const BoundaryBvh::Face& f : bvh.faces()) {
    push(out, f.a - c);
    push(out, f.e1);
    push(out, f.e2);
    out.push_back(std::bit_cast<float>(f.slot));
  }
  return out;
}

std::vector<float> lighting_data(const TetMesh& mesh, Vec3 c) {
  const PointGradients g(mesh);
  const auto& p = mesh.points();
  std::vector<float> out;
  out.reserve(24 * mesh.size());
  for (const TetMesh::Tet& t : mesh.tets()) {
    const Vec3 a = p[t[0]];
    const auto l = barycentric_gradients(p[t[1]] - a, p[t[2]] - a, p[t[3]] - a);
    push(out, a - c);
    for (int k = 0; k < 3; ++k) push(out, l[k]);
    const Vec3 g0 = g.at_point(t[0]);
    push(out, g0);
    for (int k = 1; k < 4; ++k) push(out, g.at_point(t[k]) - g0);
  }
  return out;
}

std::vector<std::int32_t> neighbor_data(const TetMesh& mesh) {
  std::vector<std::int32_t> out(4 * mesh.size());
  for (std::size_t t = 0; t < mesh.size(); ++t)
    for (int f = 0; f < 4; ++f) out[4 * t + f] = mesh.neighbor(t, f);
  return out;
}

Vec3 centre_of(const TetMesh& mesh) { return (mesh.box_lo() + mesh.box_hi()) * 0.5; }

}  // namespace

GpuTetMesh::GpuTetMesh(const std::shared_ptr<const VulkanDevice>& device, const TetMesh& mesh, bool lit)
    : GpuTetMesh(device, TetWalk(mesh), lit) {}

GpuTetMesh::GpuTetMesh(const std::shared_ptr<const VulkanDevice>& device, const TetWalk& walk, bool lit)
    : centre(centre_of(walk.mesh())),
      extent(static_cast<float>(length(walk.mesh().box_hi() - walk.mesh().box_lo()))),
      tets(device, bytes_of(tet_data(walk, centre)), "the tetrahedra"),
      neighbors(device, bytes_of(neighbor_data(walk.mesh())), "the neighbours"),
      nodes(device, bytes_of(bvh_nodes(walk.bvh(), centre, 1e-6 * extent)), "the boundary's BVH"),
      faces(device, bytes_of(bvh_faces(walk.bvh(), centre)), "the boundary faces"),
      lighting(device, bytes_of(lit ? lighting_data(walk.mesh(), centre) : std::vector<float>(1, 0.0f)),
               "the point gradients") {}

}  // namespace vri::vulkan
