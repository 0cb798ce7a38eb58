#include "gpu_array.hpp"

#include <algorithm>
#include <string>

#include "vri/error.hpp"

namespace vri::vulkan {

GpuArray::GpuArray(std::shared_ptr<const VulkanDevice> device, std::size_t bytes, const char* what)
    : bytes_(bytes), part_bytes_(std::size_t{1} << device->part_shift()) {
  if (bytes == 0) throw Error(std::string("vulkan: ") + what + " of 0 bytes");
  const std::size_t parts = (bytes + part_bytes_ - 1) / part_bytes_;
  if (parts > kParts)
    throw Error(std::string("vulkan: ") + what + " (" + std::to_string(bytes) + " bytes) exceeds " +
                std::to_string(kParts) + " storage buffers of " + device->info().name + " (" +
                std::to_string(kParts * part_bytes_) + " bytes); use --backend cpu");
  for (std::size_t k = 0; k < parts; ++k)
    parts_.push_back(std::make_unique<GpuBuffer>(device, std::min(part_bytes_, bytes - k * part_bytes_), what));
}

GpuArray::GpuArray(std::shared_ptr<const VulkanDevice> device, std::span<const std::byte> data, const char* what)
    : GpuArray(std::move(device), data.size(), what) {
  upload(data);
}

void GpuArray::upload(std::span<const std::byte> data, std::size_t offset) {
  if (offset + data.size() > bytes_) throw Error("vulkan: an upload past the end of an array");
  while (!data.empty()) {  // part by part
    const std::size_t k = offset / part_bytes_, at = offset % part_bytes_;
    const std::size_t n = std::min(data.size(), parts_[k]->size() - at);
    parts_[k]->upload(data.first(n), at);
    data = data.subspan(n);
    offset += n;
  }
}

std::array<const GpuBuffer*, GpuArray::kParts> GpuArray::bindings() const {
  std::array<const GpuBuffer*, kParts> out;
  for (int k = 0; k < kParts; ++k) out[k] = parts_[std::min<std::size_t>(k, parts_.size() - 1)].get();
  return out;
}

void GpuArray::download(std::span<std::byte> out) const {
  for (std::size_t k = 0; k < parts_.size() && k * part_bytes_ < out.size(); ++k)
    parts_[k]->download(out.subspan(k * part_bytes_, std::min(parts_[k]->size(), out.size() - k * part_bytes_)));
}

}  // namespace vri::vulkan
