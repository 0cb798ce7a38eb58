#pragma once
// A DiscreteTf (src/tables/discrete_tf.hpp) on the device, as
// shaders/discrete_tf.glsl reads it: r, g, b, tau at the table scalars, the
// split bins' first sub-pieces and the sub-pieces, in float.
#include <memory>

#include "gpu_buffer.hpp"
#include "tables/discrete_tf.hpp"

namespace vri::vulkan {

struct GpuDiscreteTf {
  GpuDiscreteTf(const std::shared_ptr<const VulkanDevice>& device, const DiscreteTf& tf);
  GpuBuffer samples, sub_begin, subs;
};

}  // namespace vri::vulkan
