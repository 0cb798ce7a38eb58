#pragma once
// The Vulkan functions vri calls, loaded at run time from the loader
// (libvulkan.so.1) instead of linked, as src/cli/ffmpeg_library does for
// FFmpeg: `vri` starts, and renders on the CPU, on a machine without the
// Vulkan loader; `--backend vulkan` there says what is missing. The types are
// those of Debian's headers (libvulkan-dev, VK_NO_PROTOTYPES).
#define VK_NO_PROTOTYPES
#include <vulkan/vulkan.h>

namespace vri::vulkan {

// Functions found through vkGetInstanceProcAddr(nullptr, ...).
#define VRI_VK_GLOBAL_FUNCTIONS(X) \
  X(vkCreateInstance) X(vkEnumerateInstanceLayerProperties) X(vkEnumerateInstanceExtensionProperties)

// Functions of an instance (and its physical and logical devices).
#define VRI_VK_INSTANCE_FUNCTIONS(X)                                                                             \
  X(vkDestroyInstance) X(vkEnumeratePhysicalDevices) X(vkGetPhysicalDeviceProperties)                            \
  X(vkGetPhysicalDeviceFeatures) X(vkGetPhysicalDeviceQueueFamilyProperties)                                     \
  X(vkGetPhysicalDeviceMemoryProperties) X(vkCreateDevice) X(vkGetDeviceProcAddr)                                \
  X(vkCreateDebugUtilsMessengerEXT) X(vkDestroyDebugUtilsMessengerEXT) X(vkEnumerateDeviceExtensionProperties)

#define VRI_VK_DEVICE_FUNCTIONS(X)                                                                               \
  X(vkDestroyDevice) X(vkGetDeviceQueue) X(vkDeviceWaitIdle) X(vkCreateBuffer) X(vkDestroyBuffer)                \
  X(vkGetBufferMemoryRequirements) X(vkAllocateMemory) X(vkFreeMemory) X(vkBindBufferMemory) X(vkMapMemory)      \
  X(vkUnmapMemory) X(vkCreateShaderModule) X(vkDestroyShaderModule) X(vkCreateDescriptorSetLayout)               \
  X(vkDestroyDescriptorSetLayout) X(vkCreatePipelineLayout) X(vkDestroyPipelineLayout)                           \
  X(vkCreateComputePipelines) X(vkDestroyPipeline) X(vkCreateDescriptorPool) X(vkDestroyDescriptorPool)          \
  X(vkAllocateDescriptorSets) X(vkUpdateDescriptorSets) X(vkCreateCommandPool) X(vkDestroyCommandPool)           \
  X(vkAllocateCommandBuffers) X(vkFreeCommandBuffers) X(vkBeginCommandBuffer) X(vkEndCommandBuffer)              \
  X(vkCmdBindPipeline) X(vkCmdBindDescriptorSets) X(vkCmdPushConstants) X(vkCmdDispatch) X(vkCmdCopyBuffer)      \
  X(vkCmdPipelineBarrier) X(vkQueueSubmit) X(vkCreateFence) X(vkDestroyFence) X(vkWaitForFences)                 \
  X(vkResetFences) X(vkResetCommandBuffer)

struct Api {
#define VRI_VK_POINTER(name) PFN_##name name = nullptr;
  PFN_vkGetInstanceProcAddr vkGetInstanceProcAddr = nullptr;
  VRI_VK_GLOBAL_FUNCTIONS(VRI_VK_POINTER)
  VRI_VK_INSTANCE_FUNCTIONS(VRI_VK_POINTER)
  VRI_VK_DEVICE_FUNCTIONS(VRI_VK_POINTER)
#undef VRI_VK_POINTER

  // Fills the instance's functions (the debug-utils pair may stay null: the
  // extension is only asked for with validation) and the device's.
  void load_instance(VkInstance instance);
  void load_device(VkDevice device);
};

// The loader's global functions, loaded once; vri::Error saying the Vulkan
// loader is missing (install libvulkan1) if it cannot be opened.
Api global_api();

// vri::Error "vulkan: WHAT failed (VK_ERROR_...)" unless result is VK_SUCCESS.
void check(VkResult result, const char* what);
const char* result_name(VkResult result);

}  // namespace vri::vulkan
