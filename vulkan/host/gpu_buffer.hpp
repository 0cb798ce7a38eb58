#pragma once
// GpuBuffer: a storage buffer in the device's memory (device-local where the
// device has it) with copies in and out. Where that memory is also visible
// to the host (integrated GPUs, lavapipe) the copies are memcpy; elsewhere
// they go through a host-visible staging buffer.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

#include "vulkan_device.hpp"

namespace vri::vulkan {

class GpuBuffer {
 public:
  // `bytes` > 0; vri::Error naming `what` ("the gradient field") if the
  // device cannot hold it.
  GpuBuffer(std::shared_ptr<const VulkanDevice> device, std::size_t bytes, const char* what = "a buffer");
  // A buffer holding `data` (not empty).
  GpuBuffer(std::shared_ptr<const VulkanDevice> device, std::span<const std::byte> data,
            const char* what = "a buffer");
  ~GpuBuffer();
  GpuBuffer(const GpuBuffer&) = delete;
  GpuBuffer& operator=(const GpuBuffer&) = delete;

  VkBuffer handle() const { return buffer_; }
  std::size_t size() const { return bytes_; }
  // Copies `data` to the buffer's bytes from `offset` on / the buffer's
  // first out.size() bytes out.
  void upload(std::span<const std::byte> data, std::size_t offset = 0);
  void download(std::span<std::byte> out) const;
  // Bytes copied in by every buffer of this process so far (what a frame
  // uploads is the difference across it; issue 47).
  static std::uint64_t uploaded_bytes();

 private:
  struct Allocation {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    bool host_visible = false;
  };
  Allocation allocate(VkBufferUsageFlags usage, VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) const;
  void free(Allocation& a) const;

  std::shared_ptr<const VulkanDevice> device_;
  std::size_t bytes_;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  bool host_visible_ = false;
};

}  // namespace vri::vulkan
