#include "pixel_kernel.hpp"

#include <algorithm>
#include <vector>

namespace vri::vulkan {

GridParams grid_params(const GridVolume& volume, int type, double termination) {
  GridParams g{};
  const auto& dims = volume.dims();
  g.sy = static_cast<std::uint32_t>(dims[0]);
  g.sz = static_cast<std::uint32_t>(dims[0]) * static_cast<std::uint32_t>(dims[1]);
  g.type = type;
  for (int a = 0; a < 3; ++a) {
    g.top[a] = static_cast<float>(dims[a] - 1);
    g.last_cell[a] = dims[a] - 2;
  }
  g.termination = static_cast<float>(termination);
  return g;
}

Image run_pixels(const std::shared_ptr<const VulkanDevice>& device, const ComputeKernel& kernel, int width,
                 int height, std::span<const GpuBuffer* const> inputs, GridParams& grid, const void* params) {
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  GpuBuffer image_buffer(device, pixels * 4 * sizeof(float));
  const std::uint64_t groups = (pixels + 63) / 64;
  const auto gx = static_cast<std::uint32_t>(std::min<std::uint64_t>(groups, device->max_workgroups_x()));
  const auto gy = static_cast<std::uint32_t>((groups + gx - 1) / gx);
  grid.pixels = static_cast<std::uint32_t>(pixels);
  grid.row_pixels = gx * 64;
  std::vector<const GpuBuffer*> buffers(inputs.begin(), inputs.end());
  buffers.push_back(&image_buffer);
  kernel.run(gx, gy, buffers, params);
  Image image(width, height);
  image_buffer.download(std::as_writable_bytes(std::span<float>(image.data())));
  return image;
}

}  // namespace vri::vulkan
