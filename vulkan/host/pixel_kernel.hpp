#pragma once
// A per-pixel march on the GPU: one invocation per pixel in groups of 64 (a
// second dispatch dimension once the first is full), the image read back as
// the Image the CPU renderer returns. Every march's push constants start
// with GridParams (shaders/grid_params.glsl).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

#include <functional>
#include <vector>

#include "compute_kernel.hpp"
#include "push_constants.h"  // GridParams
#include "vri/image.hpp"
#include "vri/volume.hpp"

namespace vri::vulkan {

// Pixels first .. first + count - 1, row by row (pixel p is (p % width, p / width)).
struct PixelSpan {
  std::size_t first = 0, count = 0;
};

// GridParams: push_constants.h (VRI_GRID_FIELDS), shared with the kernels.

// The volume's part of GridParams (the dispatch's part is set by run_pixels).
GridParams grid_params(const VulkanDevice& device, const GridVolume& volume, int type, double termination);

// Runs `kernel` over width x height pixels with `inputs` bound at 0 .. n-1
// and the image at n; the null entry of `inputs` is where the rays' input
// goes: `rays(span)`, the camera block the kernel makes the span's rays from
// (src/methods/march/ray_setup.hpp; a few hundred bytes, plus riemann's
// jitter fractions). The pixels run in chunks of at most kChunkPixels whose
// image fits one storage buffer (128 MiB on lavapipe). `params` is the
// kernel's push-constant block and `grid` its first member, which this
// completes (pixels, row_pixels).
inline constexpr std::size_t kChunkPixels = std::size_t{1} << 18;
using RaySetup = std::function<std::vector<float>(PixelSpan)>;

// A march that leaves the end of each ray to the host (preint's partial last
// slab, integrated exactly in double as on the CPU): the kernel writes
// `floats` floats a pixel at binding n + 1, and `run(span, rgba, tails)`
// completes the span's pixels (rgba: 4 floats a pixel, in place).
struct HostFinish {
  int floats = 0;
  std::function<void(PixelSpan, std::span<float>, std::span<const float>)> run;
};

Image run_pixels(const std::shared_ptr<const VulkanDevice>& device, const ComputeKernel& kernel, int width,
                 int height, std::span<const GpuBuffer* const> inputs, const RaySetup& rays, GridParams& grid,
                 const void* params, const HostFinish* finish = nullptr);

}  // namespace vri::vulkan
