#include "KernelPipelines.h"

#include "voxc/core/Errors.h"

#include <fmt/format.h>

#include <iterator>

namespace voxc::vulkan_detail {

namespace {

// Descriptor set 0 of every kernel (compiler/shaders/common.glsl), all storage buffers.
constexpr uint32_t kBindings[] = {kBindingVoxels,       kBindingChunkTable,   kBindingNoiseTables,
                                  kBindingTileRanges,  kBindingTileDirty,   kBindingActiveTiles,
                                  kBindingActiveDispatch, kBindingSkipStats,  kBindingMaterials,
                                  kBindingNonFinite,     kBindingPointSets,   kBindingScratch,
                                  kBindingSolveTables};
static_assert(std::size(kBindings) == kKernelBindingCount);
constexpr uint32_t kBindingCount = std::size(kBindings);

} // namespace

void createPipelines(VulkanContext::Impl& ctx, const std::vector<Kernel>& kernels, KernelPipelines& out) {
    VkDescriptorSetLayoutBinding bindings[kBindingCount]{};
    for (uint32_t i = 0; i < kBindingCount; ++i) {
        bindings[i].binding = kBindings[i];
        bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        bindings[i].descriptorCount = 1;
        bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    }
    VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setInfo.bindingCount = kBindingCount;
    setInfo.pBindings = bindings;
    check(ctx.api.vkCreateDescriptorSetLayout(ctx.device, &setInfo, nullptr, &out.setLayout),
          "vkCreateDescriptorSetLayout");

    VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(PushBlock)};
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &out.setLayout;
    layoutInfo.pushConstantRangeCount = 1;
    layoutInfo.pPushConstantRanges = &push;
    check(ctx.api.vkCreatePipelineLayout(ctx.device, &layoutInfo, nullptr, &out.layout), "vkCreatePipelineLayout");

    VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kBindingCount};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &poolSize;
    check(ctx.api.vkCreateDescriptorPool(ctx.device, &poolInfo, nullptr, &out.pool), "vkCreateDescriptorPool");
    VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocate.descriptorPool = out.pool;
    allocate.descriptorSetCount = 1;
    allocate.pSetLayouts = &out.setLayout;
    check(ctx.api.vkAllocateDescriptorSets(ctx.device, &allocate, &out.set), "vkAllocateDescriptorSets");

    for (const Kernel& kernel : kernels) {
        VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        moduleInfo.codeSize = kernel.spirv.size() * sizeof(uint32_t);
        moduleInfo.pCode = kernel.spirv.data();
        VkShaderModule module = VK_NULL_HANDLE;
        VkResult result = ctx.api.vkCreateShaderModule(ctx.device, &moduleInfo, nullptr, &module);
        if (result != VK_SUCCESS)
            throw InternalError(fmt::format("kernel '{}': vkCreateShaderModule failed: {}", kernel.name,
                                            resultName(result)));
        VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
        pipelineInfo.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
        pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
        pipelineInfo.stage.module = module;
        pipelineInfo.stage.pName = "main";
        pipelineInfo.layout = out.layout;
        VkPipeline pipeline = VK_NULL_HANDLE;
        result = ctx.api.vkCreateComputePipelines(ctx.device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &pipeline);
        ctx.api.vkDestroyShaderModule(ctx.device, module, nullptr);
        if (result != VK_SUCCESS)
            throw InternalError(fmt::format("kernel '{}' ({}): vkCreateComputePipelines failed: {}", kernel.name,
                                            kernel.origin, resultName(result)));
        out.pipelines.push_back(pipeline);
    }
}

void bindBuffers(VulkanContext::Impl& ctx, const KernelPipelines& pipelines,
                 const std::array<VkBuffer, kKernelBindingCount>& byBinding) {
    VkDescriptorBufferInfo buffers[kBindingCount];
    VkWriteDescriptorSet writes[kBindingCount]{};
    for (uint32_t i = 0; i < kBindingCount; ++i) {
        buffers[i] = {byBinding[kBindings[i]], 0, VK_WHOLE_SIZE};
        writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        writes[i].dstSet = pipelines.set;
        writes[i].dstBinding = kBindings[i];
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        writes[i].pBufferInfo = &buffers[i];
    }
    ctx.api.vkUpdateDescriptorSets(ctx.device, kBindingCount, writes, 0, nullptr);
}

void destroyPipelines(VulkanContext::Impl& ctx, KernelPipelines& p) {
    for (VkPipeline pipeline : p.pipelines) ctx.api.vkDestroyPipeline(ctx.device, pipeline, nullptr);
    if (p.pool) ctx.api.vkDestroyDescriptorPool(ctx.device, p.pool, nullptr); // frees the set
    if (p.layout) ctx.api.vkDestroyPipelineLayout(ctx.device, p.layout, nullptr);
    if (p.setLayout) ctx.api.vkDestroyDescriptorSetLayout(ctx.device, p.setLayout, nullptr);
    p = KernelPipelines{};
}

} // namespace voxc::vulkan_detail
