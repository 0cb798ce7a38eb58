#pragma once
// tet-raycast (SPEC §9; TetRaycastIntegrator) on a Vulkan device
// (src/methods/tet_raycast/tet_raycast.comp): the cell-to-cell walk through the mesh
// with each tetrahedron's piece looked up in the (l, s_f, s_b) table, one
// invocation per ray, in float; the tables built on the host by the scene's
// builder, uploaded once; lit sampled or interpolated as on the CPU.
#include <array>
#include <memory>
#include <optional>

#include "compute_kernel.hpp"
#include "gpu_array.hpp"
#include "gpu_scene_data.hpp"  // ShadingParams
#include "gpu_tet_mesh.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"
#include "tables/discrete_tf.hpp"

namespace vri::vulkan {

class VulkanTetRaycast final : public GpuSceneRenderer {
 public:
  VulkanTetRaycast(std::shared_ptr<const VulkanDevice> device, const Scene& scene);
  Image render(const Camera& camera, const RenderOptions& options) const override;
  std::string device_name() const override { return "vulkan: " + device_->info().name; }

 private:
  std::shared_ptr<const VulkanDevice> device_;
  const Scene& scene_;
  GpuTetMesh mesh_;
  double max_length_;
  int lengths_;
  int mode_;
  ScalarAxis axis_;  // the tables' scalar axis  // 0 unlit, 1 sampled, 2 interpolated
  std::array<std::optional<GpuArray>, 2> tables_;  // the table, or the front and back weighted tables
  ShadingParams shading_{};  // lit: the coefficients (lit 0: unlit)
  std::optional<ComputeKernel> kernel_;
  Bindings inputs() const;
};

}  // namespace vri::vulkan
