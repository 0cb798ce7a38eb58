#include "compute_kernel.hpp"

#include <utility>

#include "vri/error.hpp"

namespace vri::vulkan {

ComputeKernel::ComputeKernel(std::shared_ptr<const VulkanDevice> device, std::span<const std::uint32_t> spirv,
                             int buffers, std::uint32_t push_bytes, std::uint32_t split_arrays)
    : device_(std::move(device)), buffers_(buffers), push_bytes_(push_bytes) {
  const Api& api = device_->api();
  const VkDevice d = device_->device();
  if (static_cast<std::uint32_t>(buffers_) > device_->max_storage_buffers_per_stage())
    throw Error("vulkan: a kernel binds " + std::to_string(buffers_) + " storage buffers, over the " +
                std::to_string(device_->max_storage_buffers_per_stage()) + " this device allows a shader stage (" +
                device_->info().name + "); use --backend cpu");
  try {
    VkShaderModuleCreateInfo m{};
    m.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    m.codeSize = spirv.size_bytes();
    m.pCode = spirv.data();
    check(api.vkCreateShaderModule(d, &m, nullptr, &module_), "vkCreateShaderModule");

    std::vector<VkDescriptorSetLayoutBinding> bindings(static_cast<std::size_t>(buffers_));
    for (int i = 0; i < buffers_; ++i)
      bindings[i] = {static_cast<std::uint32_t>(i), VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT,
                     nullptr};
    VkDescriptorSetLayoutCreateInfo sl{};
    sl.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    sl.bindingCount = static_cast<std::uint32_t>(bindings.size());
    sl.pBindings = bindings.data();
    check(api.vkCreateDescriptorSetLayout(d, &sl, nullptr, &set_layout_), "vkCreateDescriptorSetLayout");

    const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, push_bytes_};
    VkPipelineLayoutCreateInfo pl{};
    pl.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    pl.setLayoutCount = 1;
    pl.pSetLayouts = &set_layout_;
    pl.pushConstantRangeCount = push_bytes_ ? 1 : 0;
    pl.pPushConstantRanges = &range;
    check(api.vkCreatePipelineLayout(d, &pl, nullptr, &layout_), "vkCreatePipelineLayout");

    VkComputePipelineCreateInfo cp{};
    cp.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
    cp.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    cp.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    cp.stage.module = module_;
    cp.stage.pName = "main";
    const VkSpecializationMapEntry entry{0, 0, sizeof split_arrays};
    const VkSpecializationInfo specialization{1, &entry, sizeof split_arrays, &split_arrays};
    cp.stage.pSpecializationInfo = &specialization;
    cp.layout = layout_;
    check(api.vkCreateComputePipelines(d, VK_NULL_HANDLE, 1, &cp, nullptr, &pipeline_), "vkCreateComputePipelines");

    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, static_cast<std::uint32_t>(buffers_)};
    VkDescriptorPoolCreateInfo dp{};
    dp.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    dp.maxSets = 1;
    dp.poolSizeCount = 1;
    dp.pPoolSizes = &size;
    check(api.vkCreateDescriptorPool(d, &dp, nullptr, &pool_), "vkCreateDescriptorPool");
    VkDescriptorSetAllocateInfo ds{};
    ds.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    ds.descriptorPool = pool_;
    ds.descriptorSetCount = 1;
    ds.pSetLayouts = &set_layout_;
    check(api.vkAllocateDescriptorSets(d, &ds, &set_), "vkAllocateDescriptorSets");
  } catch (...) {
    release();
    throw;
  }
}

ComputeKernel::~ComputeKernel() { release(); }

void ComputeKernel::release() noexcept {
  const Api& api = device_->api();
  const VkDevice d = device_->device();
  if (pool_) api.vkDestroyDescriptorPool(d, pool_, nullptr);  // frees set_
  if (pipeline_) api.vkDestroyPipeline(d, pipeline_, nullptr);
  if (layout_) api.vkDestroyPipelineLayout(d, layout_, nullptr);
  if (set_layout_) api.vkDestroyDescriptorSetLayout(d, set_layout_, nullptr);
  if (module_) api.vkDestroyShaderModule(d, module_, nullptr);
  pool_ = VK_NULL_HANDLE, pipeline_ = VK_NULL_HANDLE, layout_ = VK_NULL_HANDLE;
  set_layout_ = VK_NULL_HANDLE, module_ = VK_NULL_HANDLE, set_ = VK_NULL_HANDLE;
}

void ComputeKernel::run(std::uint32_t groups_x, std::uint32_t groups_y, std::span<const GpuBuffer* const> buffers,
                        const void* push, std::uint32_t groups_z) const {
  if (static_cast<int>(buffers.size()) != buffers_) throw Error("vulkan: a kernel run with the wrong buffers");
  const Api& api = device_->api();
  std::lock_guard lock(mutex_);
  std::vector<VkDescriptorBufferInfo> infos(buffers.size());
  std::vector<VkWriteDescriptorSet> writes(buffers.size());
  for (std::size_t i = 0; i < buffers.size(); ++i) {
    infos[i] = {buffers[i]->handle(), 0, VK_WHOLE_SIZE};
    writes[i] = {};
    writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    writes[i].dstSet = set_;
    writes[i].dstBinding = static_cast<std::uint32_t>(i);
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[i].pBufferInfo = &infos[i];
  }
  api.vkUpdateDescriptorSets(device_->device(), static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
  device_->submit([&](VkCommandBuffer cb) {
    api.vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    api.vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_, 0, nullptr);
    if (push_bytes_) api.vkCmdPushConstants(cb, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, push_bytes_, push);
    api.vkCmdDispatch(cb, groups_x, groups_y, groups_z);
    // The results visible to the copies and host reads that follow.
    VkMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_HOST_READ_BIT;
    api.vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                             VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0, nullptr,
                             0, nullptr);
  });
}

}  // namespace vri::vulkan
