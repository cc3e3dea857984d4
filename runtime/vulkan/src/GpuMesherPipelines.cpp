#include "GpuMesherPipelines.h"

#include "voxc/codegen/Spirv.h"
#include "voxc/shaders/ShaderSources.h"

#include <string>
#include <vector>

namespace voxc::vulkan_detail {

namespace {

constexpr const char* kPassFiles[kMcPassCount] = {"mc_tiles.glsl", "mc_count.glsl", "mc_vertices.glsl", "mc_materials.glsl"};

// The pass's #version line, kHasMaterials, the shared declarations, then the rest of the pass.
std::string passSource(const char* file, bool hasMaterials) {
    const std::string pass(shaderSource(file));
    const size_t firstLine = pass.find('\n') + 1;
    return pass.substr(0, firstLine) + "const bool kHasMaterials = " + (hasMaterials ? "true" : "false") + ";\n" +
           std::string(shaderSource("mc_common.glsl")) + pass.substr(firstLine);
}

VkDescriptorType descriptorType(uint32_t binding) {
    return isMcTexelBinding(binding)          ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER
           : isMcStorageTexelBinding(binding) ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER
                                              : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}

// Set 0 (McBinding) and the pipeline layout with the push block.
void createMcSet(VulkanContext::Impl& ctx, McPipelines& out) {
    std::vector<VkDescriptorSetLayoutBinding> layoutBindings(kMcBindingCount);
    for (uint32_t b = 0; b < kMcBindingCount; ++b) {
        layoutBindings[b].binding = b;
        layoutBindings[b].descriptorType = descriptorType(b);
        layoutBindings[b].descriptorCount = 1;
        layoutBindings[b].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    }
    createDescriptorSet(ctx, layoutBindings, sizeof(McPush), out);
}

} // namespace

void createMcPipelines(VulkanContext::Impl& ctx, bool hasMaterials, McPipelines& out) {
    createMcSet(ctx, out);
    for (uint32_t pass = 0; pass < kMcPassCount; ++pass) {
        const std::vector<uint32_t> spirv = codegen::compileComputeShader(kPassFiles[pass], passSource(kPassFiles[pass], hasMaterials));
        out.pipelines[pass] = createComputePipeline(ctx, out.layout, spirv, kPassFiles[pass]);
    }
}

void bindMcSet(VulkanContext::Impl& ctx, const McPipelines& pipelines, const std::array<VkBuffer, kMcBindingCount>& buffers,
               const std::array<VkBufferView, kMcBindingCount>& views) {
    std::array<VkDescriptorBufferInfo, kMcBindingCount> infos{};
    std::array<VkWriteDescriptorSet, kMcBindingCount> writes{};
    for (uint32_t b = 0; b < kMcBindingCount; ++b) {
        writes[b] = VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[b].dstSet = pipelines.set;
        writes[b].dstBinding = b;
        writes[b].descriptorCount = 1;
        writes[b].descriptorType = descriptorType(b);
        if (isMcTexelBinding(b) || isMcStorageTexelBinding(b)) {
            writes[b].pTexelBufferView = &views[b];
        } else {
            infos[b] = {buffers[b], 0, VK_WHOLE_SIZE};
            writes[b].pBufferInfo = &infos[b];
        }
    }
    ctx.api.vkUpdateDescriptorSets(ctx.device, kMcBindingCount, writes.data(), 0, nullptr);
}

void destroyMcPipelines(VulkanContext::Impl& ctx, McPipelines& pipelines) {
    for (VkPipeline& pipeline : pipelines.pipelines)
        if (pipeline) ctx.api.vkDestroyPipeline(ctx.device, pipeline, nullptr);
    destroyStorageSet(ctx, pipelines);
    pipelines = McPipelines{};
}

} // namespace voxc::vulkan_detail
