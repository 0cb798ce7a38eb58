// The Vulkan backend's entry points (include/vri/render.hpp): which
// method runs on the GPU (its renderer: the registry's make_gpu), which table builders do, and the device list of
// `vri devices`.
#include <string>
#include <vector>

#include "vri/error.hpp"
#include "vri/methods.hpp"  // check_mesh_termination
#include "vri/render.hpp"
#include "vri/scene.hpp"
#include "vulkan_device.hpp"
#include "vulkan_table_builders.hpp"

namespace vri {

bool vulkan_backend_built() { return true; }

std::unique_ptr<GpuSceneRenderer> make_vulkan_scene_renderer(const Scene& scene) {
  const std::string& m = scene.method.name;
  const MethodInfo& info = known_method(m);
  const bool grid = std::holds_alternative<GridVolume>(scene.volume);
  if (grid && !info.gpu_grid)
    throw Error("--backend vulkan: method '" + m + "' is not on the GPU yet; " +
                method_names([](const MethodInfo& i) { return i.gpu_grid; }) + " are (docs/GPU.md)");
  if (!scene.method.fast.float_math)
    throw Error("--backend vulkan: the GPU computes in float; --double needs --backend cpu");
  if (!grid) {
    if (!info.gpu_mesh)
      throw Error("--backend vulkan: method '" + m + "' on tetrahedral meshes is not on the GPU yet; " +
                  method_names([](const MethodInfo& i) { return i.gpu_mesh; }) + " is (docs/GPU.md)");
    check_mesh_termination(scene.method);  // as make_integrator on the CPU
  }
  if (!info.make_gpu) throw Error("method '" + m + "' is in the method registry without a GPU renderer");
  return info.make_gpu(scene);
}

std::unique_ptr<TableBuilder> make_vulkan_table_builder(const std::string& builder, int steps) {
  if (builder == "incremental") return std::make_unique<vulkan::VulkanIncrementalBuilder>(vulkan::VulkanDevice::shared());
  if (builder != "sliced")
    throw Error("--backend vulkan: the first-order builder '" + builder +
                "' is not on the GPU; sliced (Roettger & Ertl) and incremental (Lum et al.) are (docs/GPU.md)");
  return std::make_unique<vulkan::VulkanSlicedBuilder>(vulkan::VulkanDevice::shared(), steps);
}

std::unique_ptr<SecondOrderBuilder> make_vulkan_second_order_builder(const std::string& builder) {
  if (builder != "fast")
    throw Error("--backend vulkan: the second-order builder '" + builder +
                "' is not on the GPU; fast (El Hajjar et al.) is (docs/GPU.md)");
  return std::make_unique<vulkan::VulkanSecondOrderBuilder>(vulkan::VulkanDevice::shared());
}

std::vector<std::string> list_vulkan_devices() {
  std::vector<std::string> out;
  for (const vulkan::DeviceInfo& d : vulkan::VulkanDevice::list())
    out.push_back(std::to_string(d.index) + ": " + d.name + ", " + d.type + ", Vulkan " + d.api +
                  (d.usable ? "" : " (not usable: " + d.why_not + ")"));
  return out;
}

}  // namespace vri
