#pragma once
// What every GPU renderer of a grid holds: the shared device, the scene (kept
// alive by the caller, as SceneRenderer's), and the volume's samples on the
// device. One renderer per method derives from it (vulkan_riemann.hpp,
// vulkan_preint1.hpp).
#include <memory>
#include <optional>
#include <string>

#include "gpu_scene_data.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace vri::vulkan {

class VulkanGridRenderer : public GpuSceneRenderer {
 public:
  std::string device_name() const override { return "vulkan: " + device_->info().name; }

 protected:
  // Lit scenes: the CPU's gradient field, on the device too.
  VulkanGridRenderer(std::shared_ptr<const VulkanDevice> device, const Scene& scene)
      : device_(std::move(device)), scene_(scene), volume_(device_, scene.grid()) {
    if (!scene.lighting.enabled) return;
    shader_.emplace(scene.lighting, scene.grid());
    shading_.emplace(device_, scene.lighting, *shader_, scene.grid());
  }
  // What a lit shader reads as its gradients; unlit, the volume stands in
  // (a binding the shader never reads).
  const GpuArray& gradients() const { return shading_ ? shading_->gradients : volume_.samples; }

  std::shared_ptr<const VulkanDevice> device_;
  const Scene& scene_;
  GpuVolume volume_;
  std::optional<HeadlightShader> shader_;  // lit: the coefficients and the gradient field
  std::optional<GpuShading> shading_;
};

}  // namespace vri::vulkan
