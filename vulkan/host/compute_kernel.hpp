#pragma once
// ComputeKernel: one compute shader (SPIR-V compiled by glslc at build time,
// embedded in the binary: vulkan/CMakeLists.txt) as a pipeline whose bindings
// 0 .. n-1 are storage buffers and whose parameters are push constants;
// `split_arrays` is its specialization constant 0 (split_array.glsl's
// kSplitArrays: which input arrays come in several parts).
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "gpu_buffer.hpp"

namespace vri::vulkan {

class ComputeKernel {
 public:
  ComputeKernel(std::shared_ptr<const VulkanDevice> device, std::span<const std::uint32_t> spirv, int buffers,
                std::uint32_t push_bytes, std::uint32_t split_arrays = 0);
  ~ComputeKernel();
  ComputeKernel(const ComputeKernel&) = delete;
  ComputeKernel& operator=(const ComputeKernel&) = delete;

  // Runs groups_x x groups_y x groups_z work groups with `buffers` bound in
  // order and `push` as the push constants (push_bytes of them), and waits.
  void run(std::uint32_t groups_x, std::uint32_t groups_y, std::span<const GpuBuffer* const> buffers,
           const void* push, std::uint32_t groups_z = 1) const;

 private:
  std::shared_ptr<const VulkanDevice> device_;
  int buffers_;
  std::uint32_t push_bytes_;
  VkShaderModule module_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  mutable std::mutex mutex_;  // the one descriptor set
  void release() noexcept;
};

}  // namespace vri::vulkan
