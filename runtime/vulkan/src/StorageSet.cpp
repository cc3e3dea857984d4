#include "StorageSet.h"

#include "voxc/core/Errors.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace voxc::vulkan_detail {

namespace {

std::vector<VkDescriptorSetLayoutBinding> storageBindings(std::span<const uint32_t> bindings) {
    std::vector<VkDescriptorSetLayoutBinding> layoutBindings(bindings.size());
    for (size_t i = 0; i < bindings.size(); ++i) {
        layoutBindings[i].binding = bindings[i];
        layoutBindings[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        layoutBindings[i].descriptorCount = 1;
        layoutBindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    }
    return layoutBindings;
}

void createLayouts(VulkanContext::Impl& ctx, std::span<const VkDescriptorSetLayoutBinding> bindings, uint32_t pushBytes,
                   VkDescriptorSetLayout& setLayout, VkPipelineLayout& layout) {
    VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setInfo.bindingCount = uint32_t(bindings.size());
    setInfo.pBindings = bindings.data();
    check(ctx.api.vkCreateDescriptorSetLayout(ctx.device, &setInfo, nullptr, &setLayout), "vkCreateDescriptorSetLayout");

    const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes};
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &setLayout;
    layoutInfo.pushConstantRangeCount = 1;
    layoutInfo.pPushConstantRanges = &push;
    check(ctx.api.vkCreatePipelineLayout(ctx.device, &layoutInfo, nullptr, &layout), "vkCreatePipelineLayout");
}

} // namespace

void createStorageLayout(VulkanContext::Impl& ctx, std::span<const uint32_t> bindings, uint32_t pushBytes,
                         VkDescriptorSetLayout& setLayout, VkPipelineLayout& layout) {
    createLayouts(ctx, storageBindings(bindings), pushBytes, setLayout, layout);
}

void createDescriptorSet(VulkanContext::Impl& ctx, std::span<const VkDescriptorSetLayoutBinding> bindings,
                         uint32_t pushBytes, StorageSet& out) {
    createLayouts(ctx, bindings, pushBytes, out.setLayout, out.layout);

    // One pool size per descriptor type the bindings use.
    std::vector<VkDescriptorPoolSize> poolSizes;
    for (const VkDescriptorSetLayoutBinding& binding : bindings) {
        auto it = std::find_if(poolSizes.begin(), poolSizes.end(),
                               [&](const VkDescriptorPoolSize& size) { return size.type == binding.descriptorType; });
        if (it == poolSizes.end()) it = poolSizes.insert(poolSizes.end(), {binding.descriptorType, 0});
        it->descriptorCount += binding.descriptorCount;
    }
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = uint32_t(poolSizes.size());
    poolInfo.pPoolSizes = poolSizes.data();
    check(ctx.api.vkCreateDescriptorPool(ctx.device, &poolInfo, nullptr, &out.pool), "vkCreateDescriptorPool");
    VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocate.descriptorPool = out.pool;
    allocate.descriptorSetCount = 1;
    allocate.pSetLayouts = &out.setLayout;
    check(ctx.api.vkAllocateDescriptorSets(ctx.device, &allocate, &out.set), "vkAllocateDescriptorSets");
}

void createStorageSet(VulkanContext::Impl& ctx, std::span<const uint32_t> bindings, uint32_t pushBytes,
                      StorageSet& out) {
    createDescriptorSet(ctx, storageBindings(bindings), pushBytes, out);
}

VkPipeline createComputePipeline(VulkanContext::Impl& ctx, VkPipelineLayout layout, std::span<const uint32_t> spirv,
                                 const std::string& what) {
    VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    moduleInfo.codeSize = spirv.size() * sizeof(uint32_t);
    moduleInfo.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    VkResult result = ctx.api.vkCreateShaderModule(ctx.device, &moduleInfo, nullptr, &module);
    if (result != VK_SUCCESS)
        throw InternalError(fmt::format("{}: vkCreateShaderModule failed: {}", what, resultName(result)));
    VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    pipelineInfo.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipelineInfo.stage.module = module;
    pipelineInfo.stage.pName = "main";
    pipelineInfo.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    result = ctx.api.vkCreateComputePipelines(ctx.device, ctx.pipelineCache, 1, &pipelineInfo, nullptr, &pipeline);
    ctx.api.vkDestroyShaderModule(ctx.device, module, nullptr);
    if (result != VK_SUCCESS)
        throw InternalError(fmt::format("{}: vkCreateComputePipelines failed: {}", what, resultName(result)));
    return pipeline;
}

void writeStorageBindings(VulkanContext::Impl& ctx, VkDescriptorSet set, std::span<const uint32_t> bindings,
                          std::span<const VkBuffer> buffers) {
    VOXC_ASSERT(bindings.size() == buffers.size());
    std::vector<VkDescriptorBufferInfo> infos(bindings.size());
    std::vector<VkWriteDescriptorSet> writes(bindings.size(), VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET});
    for (size_t i = 0; i < bindings.size(); ++i) {
        infos[i] = {buffers[i], 0, VK_WHOLE_SIZE};
        writes[i].dstSet = set;
        writes[i].dstBinding = bindings[i];
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        writes[i].pBufferInfo = &infos[i];
    }
    ctx.api.vkUpdateDescriptorSets(ctx.device, uint32_t(writes.size()), writes.data(), 0, nullptr);
}

void destroyStorageSet(VulkanContext::Impl& ctx, StorageSet& s) {
    if (s.pool) ctx.api.vkDestroyDescriptorPool(ctx.device, s.pool, nullptr); // frees the set
    if (s.layout) ctx.api.vkDestroyPipelineLayout(ctx.device, s.layout, nullptr);
    if (s.setLayout) ctx.api.vkDestroyDescriptorSetLayout(ctx.device, s.setLayout, nullptr);
    s = StorageSet{};
}

} // namespace voxc::vulkan_detail
