#include "vulkan_api.hpp"

#include <dlfcn.h>

#include <string>

#include "vri/error.hpp"

namespace vri::vulkan {

namespace {

PFN_vkGetInstanceProcAddr open_loader() {
  // The loader's soname (Debian's libvulkan1); it finds the drivers (ICDs) itself.
  void* handle = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw Error(std::string("vulkan: cannot load the Vulkan loader libvulkan.so.1 (") + (why ? why : "?") +
                "); install libvulkan1 and a driver (mesa-vulkan-drivers for the CPU), or use --backend cpu");
  }
  auto* get = reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(handle, "vkGetInstanceProcAddr"));
  if (!get) throw Error("vulkan: libvulkan.so.1 lacks vkGetInstanceProcAddr");
  return get;  // the loader stays loaded for the process
}

}  // namespace

Api global_api() {
  static const PFN_vkGetInstanceProcAddr get = open_loader();  // a failed load throws and is retried next time
  Api api;
  api.vkGetInstanceProcAddr = get;
#define VRI_VK_LOAD(name)                                                                 \
  api.name = reinterpret_cast<PFN_##name>(get(nullptr, #name));                           \
  if (!api.name) throw Error("vulkan: the loader lacks " #name);
  VRI_VK_GLOBAL_FUNCTIONS(VRI_VK_LOAD)
#undef VRI_VK_LOAD
  return api;
}

void Api::load_instance(VkInstance instance) {
#define VRI_VK_LOAD(name) name = reinterpret_cast<PFN_##name>(vkGetInstanceProcAddr(instance, #name));
  VRI_VK_INSTANCE_FUNCTIONS(VRI_VK_LOAD)
#undef VRI_VK_LOAD
  if (!vkDestroyInstance || !vkEnumeratePhysicalDevices || !vkCreateDevice || !vkGetDeviceProcAddr)
    throw Error("vulkan: the instance lacks core functions");
}

void Api::load_device(VkDevice device) {
#define VRI_VK_LOAD(name)                                                        \
  name = reinterpret_cast<PFN_##name>(vkGetDeviceProcAddr(device, #name));       \
  if (!name) throw Error("vulkan: the device lacks " #name);
  VRI_VK_DEVICE_FUNCTIONS(VRI_VK_LOAD)
#undef VRI_VK_LOAD
}

const char* result_name(VkResult result) {
  switch (result) {
    case VK_SUCCESS: return "VK_SUCCESS";
    case VK_NOT_READY: return "VK_NOT_READY";
    case VK_TIMEOUT: return "VK_TIMEOUT";
    case VK_INCOMPLETE: return "VK_INCOMPLETE";
    case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_MEMORY_MAP_FAILED: return "VK_ERROR_MEMORY_MAP_FAILED";
    case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
    case VK_ERROR_TOO_MANY_OBJECTS: return "VK_ERROR_TOO_MANY_OBJECTS";
    default: return "a VkResult error";
  }
}

void check(VkResult result, const char* what) {
  if (result != VK_SUCCESS) throw Error(std::string("vulkan: ") + what + " failed (" + result_name(result) + ")");
}

}  // namespace vri::vulkan
