#pragma once
// What every GPU renderer of a grid holds: the shared device, the scene (kept
// alive by the caller, as SceneRenderer's), and the volume's samples on the
// device. One renderer per method derives from it (vulkan_riemann.hpp,
// vulkan_preint1.hpp).
#include <memory>
#include <string>

#include "gpu_scene_data.hpp"
#include "vri/render/backend.hpp"
#include "vri/scene/scene.hpp"

namespace vri::vulkan {

class VulkanGridRenderer : public GpuSceneRenderer {
 public:
  std::string device_name() const override { return "vulkan: " + device_->info().name; }

 protected:
  VulkanGridRenderer(std::shared_ptr<const VulkanDevice> device, const Scene& scene)
      : device_(std::move(device)), scene_(scene), volume_(device_, scene.grid()) {}

  std::shared_ptr<const VulkanDevice> device_;
  const Scene& scene_;
  GpuVolume volume_;
};

}  // namespace vri::vulkan
