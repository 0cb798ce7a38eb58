#include "pixel_kernel.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include "vri/memory.hpp"

namespace vri::vulkan {

GridParams grid_params(const VulkanDevice& device, const GridVolume& volume, int type, double termination) {
  GridParams g{};
  const auto& dims = volume.dims();
  g.sy = static_cast<std::uint32_t>(dims[0]);
  g.sz = static_cast<std::uint32_t>(dims[0]) * static_cast<std::uint32_t>(dims[1]);
  g.type = type;
  for (int a = 0; a < 3; ++a) g.last_cell[a] = dims[a] - 2;
  // The CPU stops once T < termination in double: the shader compares its
  // double-float T with the same double, split in two floats.
  g.termination = static_cast<float>(termination);
  g.termination_lo = static_cast<float>(termination - static_cast<double>(g.termination));
  g.part_shift = device.part_shift();
  return g;
}

Image run_pixels(const std::shared_ptr<const VulkanDevice>& device, const ComputeKernel& kernel, int width,
                 int height, std::span<const GpuBuffer* const> inputs, const RaySetup& rays, GridParams& grid,
                 const void* params, const HostFinish* finish) {
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  const std::size_t pixel_bytes = 4 * sizeof(float);
  const std::size_t tail_floats = finish ? static_cast<std::size_t>(finish->floats) : 0;
  // Each of the chunk's buffers fits one storage buffer: the image, the
  // rays' ends, and the camera block (its extras, at most 8 bytes a pixel,
  // fit where the image's 16 do).
  const std::size_t widest = std::max(pixel_bytes, tail_floats * sizeof(float));
  const std::size_t chunk = std::max<std::size_t>(
      64, std::min<std::size_t>({pixels, kChunkPixels, device->max_storage_buffer_bytes() / widest}));
  Image image(width, height);
  std::vector<float> tails;
  for (std::size_t first = 0; first < pixels; first += chunk) {
    const std::size_t n = std::min(chunk, pixels - first);
    const std::vector<float> block = rays({first, n});
    const MemoryCharge charge(block.size() + n * tail_floats, sizeof(float), "the rays of a chunk of pixels");
    const GpuBuffer ray_buffer(device, std::as_bytes(std::span<const float>(block)), "the rays");
    GpuBuffer image_buffer(device, n * pixel_bytes, "the image");
    std::optional<GpuBuffer> tail_buffer;
    if (finish) tail_buffer.emplace(device, n * tail_floats * sizeof(float), "the rays' ends");
    const std::uint64_t groups = (n + 63) / 64;
    const auto gx = static_cast<std::uint32_t>(std::min<std::uint64_t>(groups, device->max_workgroups_x()));
    const auto gy = static_cast<std::uint32_t>((groups + gx - 1) / gx);
    grid.pixels = static_cast<std::uint32_t>(n);
    grid.row_pixels = gx * 64;
    std::vector<const GpuBuffer*> buffers(inputs.begin(), inputs.end());
    for (const GpuBuffer*& b : buffers)
      if (!b) b = &ray_buffer;
    buffers.push_back(&image_buffer);
    if (tail_buffer) buffers.push_back(&*tail_buffer);
    kernel.run(gx, gy, buffers, params);
    const std::span<float> rgba = std::span<float>(image.data()).subspan(4 * first, 4 * n);
    image_buffer.download(std::as_writable_bytes(rgba));
    if (finish) {
      tails.resize(n * tail_floats);
      tail_buffer->download(std::as_writable_bytes(std::span<float>(tails)));
      finish->run({first, n}, rgba, tails);
    }
  }
  return image;
}

}  // namespace vri::vulkan
