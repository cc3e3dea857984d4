#include "GpuMesherPipelines.h"

#include "voxc/codegen/Spirv.h"
#include "voxc/shaders/ShaderSources.h"

#include <string>

namespace voxc::vulkan_detail {

namespace {

constexpr const char* kPassFiles[kMcPassCount] = {"mc_chunks.glsl", "mc_count.glsl", "mc_scan.glsl", "mc_compact.glsl",
                                                   "mc_emit.glsl"};

// The pass's #version line, then the shared declarations, then the rest of the pass.
std::string passSource(const char* file) {
    const std::string pass(shaderSource(file));
    const size_t firstLine = pass.find('\n') + 1;
    return pass.substr(0, firstLine) + std::string(shaderSource("mc_common.glsl")) + pass.substr(firstLine);
}

} // namespace

void createMcPipelines(VulkanContext::Impl& ctx, McPipelines& out) {
    VkDescriptorSetLayoutBinding bindings[kMcBindingCount]{};
    for (uint32_t i = 0; i < kMcBindingCount; ++i) {
        bindings[i].binding = i;
        bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        bindings[i].descriptorCount = 1;
        bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    }
    VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setInfo.bindingCount = kMcBindingCount;
    setInfo.pBindings = bindings;
    check(ctx.api.vkCreateDescriptorSetLayout(ctx.device, &setInfo, nullptr, &out.setLayout), "vkCreateDescriptorSetLayout");

    VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(McPush)};
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &out.setLayout;
    layoutInfo.pushConstantRangeCount = 1;
    layoutInfo.pPushConstantRanges = &push;
    check(ctx.api.vkCreatePipelineLayout(ctx.device, &layoutInfo, nullptr, &out.layout), "vkCreatePipelineLayout");

    VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kMcBindingCount};
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

    for (uint32_t pass = 0; pass < kMcPassCount; ++pass) {
        const std::vector<uint32_t> spirv = codegen::compileComputeShader(kPassFiles[pass], passSource(kPassFiles[pass]));
        VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        moduleInfo.codeSize = spirv.size() * sizeof(uint32_t);
        moduleInfo.pCode = spirv.data();
        VkShaderModule module = VK_NULL_HANDLE;
        check(ctx.api.vkCreateShaderModule(ctx.device, &moduleInfo, nullptr, &module), "vkCreateShaderModule");
        VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
        pipelineInfo.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
        pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
        pipelineInfo.stage.module = module;
        pipelineInfo.stage.pName = "main";
        pipelineInfo.layout = out.layout;
        const VkResult result =
            ctx.api.vkCreateComputePipelines(ctx.device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &out.pipelines[pass]);
        ctx.api.vkDestroyShaderModule(ctx.device, module, nullptr);
        check(result, "vkCreateComputePipelines");
    }
}

void bindMcBuffers(VulkanContext::Impl& ctx, const McPipelines& pipelines, const std::array<VkBuffer, kMcBindingCount>& buffers,
                   uint32_t first, uint32_t last) {
    VkDescriptorBufferInfo infos[kMcBindingCount]{};
    VkWriteDescriptorSet writes[kMcBindingCount]{};
    uint32_t count = 0;
    for (uint32_t b = first; b < last; ++b, ++count) {
        infos[count] = {buffers[b], 0, VK_WHOLE_SIZE};
        writes[count] = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[count].dstSet = pipelines.set;
        writes[count].dstBinding = b;
        writes[count].descriptorCount = 1;
        writes[count].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        writes[count].pBufferInfo = &infos[count];
    }
    ctx.api.vkUpdateDescriptorSets(ctx.device, count, writes, 0, nullptr);
}

void destroyMcPipelines(VulkanContext::Impl& ctx, McPipelines& pipelines) {
    for (VkPipeline& pipeline : pipelines.pipelines)
        if (pipeline) ctx.api.vkDestroyPipeline(ctx.device, pipeline, nullptr);
    if (pipelines.pool) ctx.api.vkDestroyDescriptorPool(ctx.device, pipelines.pool, nullptr);
    if (pipelines.layout) ctx.api.vkDestroyPipelineLayout(ctx.device, pipelines.layout, nullptr);
    if (pipelines.setLayout) ctx.api.vkDestroyDescriptorSetLayout(ctx.device, pipelines.setLayout, nullptr);
    pipelines = McPipelines{};
}

} // namespace voxc::vulkan_detail
