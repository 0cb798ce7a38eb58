#pragma once
// GpuArray: an array that may be larger than one storage buffer (the
// device's maxStorageBufferRange: 128 MiB on lavapipe, where a 256^3
// second-order table takes 256 MiB and a 256^3 volume's gradient field 192
// MiB), held as up to kParts buffers of 2^part_shift bytes each, the last one
// shorter. The shaders read it through shaders/split_array.glsl, which picks
// the part from the index. Element sizes are powers of two up to 16 bytes, so
// no element straddles two parts.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "gpu_buffer.hpp"

namespace vri::vulkan {

class GpuArray {
 public:
  static constexpr int kParts = 4;
  // An array of `bytes` (> 0); vri::Error naming `what` beyond kParts parts.
  GpuArray(std::shared_ptr<const VulkanDevice> device, std::size_t bytes, const char* what);
  // An array holding `data` (not empty).
  GpuArray(std::shared_ptr<const VulkanDevice> device, std::span<const std::byte> data, const char* what);

  std::size_t size() const { return bytes_; }
  bool split() const { return parts_.size() > 1; }
  // The buffers for a SPLIT_INPUT's or SPLIT_OUTPUT's kParts bindings: the
  // parts, the last one repeated where there are fewer.
  std::array<const GpuBuffer*, kParts> bindings() const;
  void upload(std::span<const std::byte> data, std::size_t offset = 0);  // to bytes offset .. offset + data.size()
  void download(std::span<std::byte> out) const;  // the first out.size() bytes

 private:
  std::size_t bytes_, part_bytes_;
  std::vector<std::unique_ptr<GpuBuffer>> parts_;
};

// A kernel's bindings in order: whole buffers, kParts for each array, and
// nullptr where run_pixels puts the rays.
class Bindings {
 public:
  Bindings& add(const GpuBuffer* b) {
    list_.push_back(b);
    return *this;
  }
  Bindings& add(const GpuArray& a) {
    for (const GpuBuffer* b : a.bindings()) list_.push_back(b);
    if (a.split()) split_ |= 1u << arrays_;
    ++arrays_;
    return *this;
  }
  std::span<const GpuBuffer* const> list() const { return list_; }
  // Bit k: the k-th array added has several parts (split_array.glsl's
  // kSplitArrays, a ComputeKernel's `split_arrays`).
  std::uint32_t split_arrays() const { return split_; }

 private:
  std::vector<const GpuBuffer*> list_;
  std::uint32_t arrays_ = 0, split_ = 0;
};

}  // namespace vri::vulkan
