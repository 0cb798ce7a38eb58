#pragma once
// A scene's data on the device, the same for every GPU method: the volume's
// samples packed in 32-bit words in their stored type (grid_sampler.glsl)
// and the transfer function as FloatTransferFunction holds it
// (transfer_function.glsl).
#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include "gpu_array.hpp"
#include "push_constants.h"  // ShadingParams, SkipParams, TfParams
#include "gpu_buffer.hpp"
#include "shading/headlight_shader.hpp"
#include "transfer/float_transfer_function.hpp"
#include "volume/empty_space.hpp"
#include "vri/volume.hpp"

namespace vri::vulkan {

// The shaders address voxels with 32-bit unsigned offsets (grid_sampler.glsl:
// the sample index, 3 x it for the gradients' floats; a uint8 volume's index
// is 4 x its word's). vri::Error for a volume whose offsets would wrap, before
// anything is allocated: four 2 GiB buffers hold 2^33 uint8 voxels, which
// would be sampled at wrapped offsets, a silent wrong image (issue 47).
// GridVolume::kMaxSamples (2^30) keeps every grid under it today; this holds
// the line when that cap rises (bricked volumes, issue 49).
void check_shader_addressable(std::uint64_t voxels);

struct GpuVolume {
  GpuVolume(std::shared_ptr<const VulkanDevice> device, const GridVolume& volume);
  GpuArray samples;
  int type;  // grid_sampler.glsl's kUInt8, kUInt16, kInt16, kFloat32
};

// SPEC §5 on the device: the gradient field the CPU computes (three floats a
// grid point, shading.glsl) and the coefficients, as the shaders' push
// constants take them.
struct GpuShading {
  GpuShading(std::shared_ptr<const VulkanDevice> device, const Lighting& lighting, const HeadlightShader& shader,
             const GridVolume& volume);
  GpuArray gradients;
  float ka, kd, ks, shininess, flat;
};

// The shaders' lighting push constants (push_constants.h): lit 0 without
// `shading`, else `mode`.
ShadingParams shading_params(const std::optional<GpuShading>& shading, int mode);


// Empty-space skipping on the device (shaders/empty_space.glsl): the macro
// cells (macro_cells.hpp, 8 grid cells a side) the CPU classified against the
// method's transfer function or table (EmptySpace), one bit each. `space`
// null (skipping off): one word, nothing empty.
// Its push constants: SkipParams (push_constants.h).
struct GpuEmptySpace {
  GpuEmptySpace(std::shared_ptr<const VulkanDevice> device, const GridVolume& volume, const EmptySpace* space);
  GpuBuffer bits;
  SkipParams params;
};

struct GpuTransferFunction {
  GpuTransferFunction(std::shared_ptr<const VulkanDevice> device, const FloatTransferFunction& tf);
  GpuBuffer values;  // breakpoints, s_ref, value r g b tau, slope r g b tau; `segments` each
  GpuBuffer bins;    // first segment per bin
  int segments;
  float lo, scale;
  TfParams params() const { return {lo, scale, FloatTransferFunction::kBins, segments}; }
};

// Their inputs in binding order: the volume, three tables (the table, or
// the weighted ones), the gradients, the rays (null), the empty macro
// cells; where a mode does not read an array, the volume stands in for it.
Bindings table_march_inputs(const GpuVolume& volume, const std::array<std::optional<GpuArray>, 3>& tables,
                            const std::optional<GpuShading>& shading, const GpuEmptySpace& empty);

}  // namespace vri::vulkan
