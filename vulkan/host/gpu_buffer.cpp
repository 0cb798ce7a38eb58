#include "gpu_buffer.hpp"

#include <atomic>
#include <cstring>
#include <utility>

#include "vri/error.hpp"

namespace vri::vulkan {

GpuBuffer::GpuBuffer(std::shared_ptr<const VulkanDevice> device, std::size_t bytes, const char* what)
    : device_(std::move(device)), bytes_(bytes) {
  if (bytes_ == 0) throw Error(std::string("vulkan: ") + what + " of 0 bytes");
  if (bytes_ > device_->max_storage_buffer_bytes())
    throw Error(std::string("vulkan: ") + what + " (" + std::to_string(bytes_) +
                " bytes) exceeds the largest storage buffer of " + device_->info().name + " (" +
                std::to_string(device_->max_storage_buffer_bytes()) + " bytes); use --backend cpu");
  Allocation a = allocate(VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                              VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                          VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT,
                          VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  buffer_ = a.buffer, memory_ = a.memory, host_visible_ = a.host_visible;
}

GpuBuffer::GpuBuffer(std::shared_ptr<const VulkanDevice> device, std::span<const std::byte> data,
                     const char* what)
    : GpuBuffer(std::move(device), data.size(), what) {
  upload(data);
}

GpuBuffer::~GpuBuffer() {
  Allocation a{buffer_, memory_, host_visible_};
  free(a);
}

GpuBuffer::Allocation GpuBuffer::allocate(VkBufferUsageFlags usage, VkMemoryPropertyFlags required,
                                          VkMemoryPropertyFlags preferred) const {
  const Api& api = device_->api();
  Allocation a;
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = bytes_;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  check(api.vkCreateBuffer(device_->device(), &info, nullptr, &a.buffer), "vkCreateBuffer");
  try {
    VkMemoryRequirements need;
    api.vkGetBufferMemoryRequirements(device_->device(), a.buffer, &need);
    const std::uint32_t type = device_->memory_type(need.memoryTypeBits, required, preferred);
    VkMemoryAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    alloc.allocationSize = need.size;
    alloc.memoryTypeIndex = type;
    const VkResult r = api.vkAllocateMemory(device_->device(), &alloc, nullptr, &a.memory);
    if (r == VK_ERROR_OUT_OF_DEVICE_MEMORY || r == VK_ERROR_OUT_OF_HOST_MEMORY)
      throw Error("vulkan: out of memory allocating " + std::to_string(bytes_) + " bytes on " + device_->info().name);
    check(r, "vkAllocateMemory");
    check(api.vkBindBufferMemory(device_->device(), a.buffer, a.memory, 0), "vkBindBufferMemory");
    const VkMemoryPropertyFlags host = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    a.host_visible = (device_->memory_flags(type) & host) == host;
  } catch (...) {
    free(a);
    throw;
  }
  return a;
}

void GpuBuffer::free(Allocation& a) const {
  const Api& api = device_->api();
  if (a.buffer) api.vkDestroyBuffer(device_->device(), a.buffer, nullptr);
  if (a.memory) api.vkFreeMemory(device_->device(), a.memory, nullptr);
  a = {};
}

namespace {

// The host-visible memory `memory` mapped for the duration of `use(pointer)`.
template <class Use>
void mapped(const Api& api, VkDevice device, VkDeviceMemory memory, std::size_t bytes, Use&& use,
            std::size_t offset = 0) {
  void* p = nullptr;
  check(api.vkMapMemory(device, memory, offset, bytes, 0, &p), "vkMapMemory");
  use(static_cast<std::byte*>(p));
  api.vkUnmapMemory(device, memory);
}

std::atomic<std::uint64_t> uploaded{0};

}  // namespace

std::uint64_t GpuBuffer::uploaded_bytes() { return uploaded.load(); }

void GpuBuffer::upload(std::span<const std::byte> data, std::size_t offset) {
  if (offset > bytes_ || data.size() > bytes_ - offset) throw Error("vulkan: upload larger than its buffer");
  if (data.empty()) return;
  uploaded.fetch_add(data.size(), std::memory_order_relaxed);
  const Api& api = device_->api();
  if (host_visible_) {
    mapped(
        api, device_->device(), memory_, data.size(), [&](std::byte* p) { std::memcpy(p, data.data(), data.size()); },
        offset);
    return;
  }
  Allocation staging = allocate(VK_BUFFER_USAGE_TRANSFER_SRC_BIT, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                                       VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, 0);
  try {
    mapped(api, device_->device(), staging.memory, data.size(),
           [&](std::byte* p) { std::memcpy(p, data.data(), data.size()); });
    device_->submit([&](VkCommandBuffer cb) {
      const VkBufferCopy region{0, offset, data.size()};
      api.vkCmdCopyBuffer(cb, staging.buffer, buffer_, 1, &region);
    });
  } catch (...) {
    free(staging);
    throw;
  }
  free(staging);
}

void GpuBuffer::download(std::span<std::byte> out) const {
  if (out.size() > bytes_) throw Error("vulkan: download larger than its buffer");
  if (out.empty()) return;
  const Api& api = device_->api();
  if (host_visible_) {
    mapped(api, device_->device(), memory_, out.size(), [&](std::byte* p) { std::memcpy(out.data(), p, out.size()); });
    return;
  }
  Allocation staging = allocate(
      VK_BUFFER_USAGE_TRANSFER_DST_BIT, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, 0);
  try {
    device_->submit([&](VkCommandBuffer cb) {
      const VkBufferCopy region{0, 0, out.size()};
      api.vkCmdCopyBuffer(cb, buffer_, staging.buffer, 1, &region);
    });
    mapped(api, device_->device(), staging.memory, out.size(),
           [&](std::byte* p) { std::memcpy(out.data(), p, out.size()); });
  } catch (...) {
    free(staging);
    throw;
  }
  free(staging);
}

}  // namespace vri::vulkan
