#include "vri/render.hpp"

#include "vri/error.hpp"
#include "tables/second_order_table.hpp"
#include "tables/table_builder.hpp"

namespace vri {

Backend parse_backend(const std::string& name) {
  if (name == "cpu") return Backend::Cpu;
  if (name == "vulkan") return Backend::Vulkan;
  throw Error("backend must be cpu or vulkan, not '" + name + "'");
}

std::string backend_name(Backend backend) { return backend == Backend::Cpu ? "cpu" : "vulkan"; }

#if !VRI_VULKAN
// This build has no Vulkan backend (vulkan/CMakeLists.txt provides these otherwise).
namespace {
const char* const kNotBuilt = "this vri was built without the Vulkan backend (install libvulkan-dev and glslc, then rebuild)";
}  // namespace

bool vulkan_backend_built() { return false; }

std::unique_ptr<GpuSceneRenderer> make_vulkan_scene_renderer(const Scene&) {
  throw Error(kNotBuilt);
}

std::unique_ptr<TableBuilder> make_vulkan_table_builder(const std::string&, int) {
  throw Error(kNotBuilt);
}

std::unique_ptr<SecondOrderBuilder> make_vulkan_second_order_builder(const std::string&) {
  throw Error(kNotBuilt);
}

std::vector<std::string> list_vulkan_devices() {
  throw Error(kNotBuilt);
}
#endif

}  // namespace vri
