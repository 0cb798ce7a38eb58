#pragma once
// VulkanDevice: one Vulkan instance and one logical device with a compute
// queue, shared by every GPU renderer of the process (creating a device costs
// milliseconds to seconds; a viewer renders many frames). The device is the
// best the loader offers - a discrete GPU, then an integrated one, a virtual
// one, then a CPU implementation (Mesa's lavapipe) - or the one whose index in
// `vri devices` the environment variable VRI_VULKAN_DEVICE names.
// VRI_VULKAN_VALIDATION=1 turns on the Khronos validation layer; its
// messages go to stderr and are counted (the tests require none).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "vulkan_api.hpp"

namespace vri::vulkan {

struct DeviceInfo {
  int index;               // in the loader's order: VRI_VULKAN_DEVICE=index picks it
  std::string name;        // "llvmpipe (LLVM 15.0.6, 256 bits)", "NVIDIA H100 ..."
  std::string type;        // "discrete GPU", "integrated GPU", "virtual GPU", "CPU", "other"
  std::string api;         // "1.3.230"
  bool usable;             // a compute queue and the features vri needs
  std::string why_not;     // when not usable
};

// The memory type memory_type() picks from `memory`: one with all of
// `required` among those `type_bits` allows, preferring one with `preferred`
// too. Where device-local memory is required, only the largest device-local
// heap is taken (issue 47): a discrete GPU without resizable BAR also has a
// ~256 MiB device-local heap that the host can map, and preferring it for
// mapping filled it; the big heap is then written through a staging buffer.
std::uint32_t choose_memory_type(const VkPhysicalDeviceMemoryProperties& memory, std::uint32_t type_bits,
                                 VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred);

class VulkanDevice {
 public:
  // The process's device, created on first use and kept until the process
  // ends; vri::Error with one line when there is no loader, no device or no
  // usable one (and the next call tries again).
  static std::shared_ptr<VulkanDevice> shared();
  // Every device the loader finds (an empty list when there are none);
  // vri::Error only when the loader itself is missing.
  static std::vector<DeviceInfo> list();
  // Messages of the validation layer so far, in this process.
  static std::size_t validation_messages();

  ~VulkanDevice();
  VulkanDevice(const VulkanDevice&) = delete;
  VulkanDevice& operator=(const VulkanDevice&) = delete;

  const Api& api() const { return api_; }
  VkDevice device() const { return device_; }
  const DeviceInfo& info() const { return info_; }
  // Whether the validation layer watches this device (VRI_VULKAN_VALIDATION).
  bool validating() const { return messenger_ != VK_NULL_HANDLE; }
  // A memory type with all of `required` among those `type_bits` allows
  // (preferring one that also has `preferred`); vri::Error if none. See
  // choose_memory_type.
  std::uint32_t memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags required,
                            VkMemoryPropertyFlags preferred = 0) const;
  VkMemoryPropertyFlags memory_flags(std::uint32_t type) const { return memory_.memoryTypes[type].propertyFlags; }
  std::uint32_t max_workgroups_x() const { return max_groups_x_; }
  // The largest storage buffer (maxStorageBufferRange, or less where
  // VRI_VULKAN_MAX_BUFFER_BYTES says so).
  std::uint64_t max_storage_buffer_bytes() const { return max_storage_bytes_; }
  // Storage buffers one kernel may bind (maxPerStageDescriptorStorageBuffers).
  std::uint32_t max_storage_buffers_per_stage() const { return max_buffers_per_stage_; }
  // log2 of the bytes in each part of a GpuArray (gpu_array.hpp): the largest
  // power of two a storage buffer holds, at most 2^31.
  std::uint32_t part_shift() const { return part_shift_; }

  // Records commands with `record` into a one-time command buffer, submits
  // it and waits; one submission at a time (the queue is shared).
  template <class Record>
  void submit(Record&& record) const {
    std::lock_guard lock(queue_mutex_);
    begin();
    record(command_buffer_);
    end_and_wait();
  }

 private:
  VulkanDevice();
  void release() noexcept;  // what the constructor made, in reverse
  void begin() const;
  void end_and_wait() const;

  Api api_;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer command_buffer_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  VkPhysicalDeviceMemoryProperties memory_{};
  std::uint32_t queue_family_ = 0, max_groups_x_ = 0, max_buffers_per_stage_ = 0;
  std::uint64_t max_storage_bytes_ = 0;
  std::uint32_t part_shift_ = 0;
  DeviceInfo info_;
  mutable std::mutex queue_mutex_;
};

}  // namespace vri::vulkan
