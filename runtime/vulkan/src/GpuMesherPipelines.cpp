#include "GpuMesherPipelines.h"

#include "voxc/codegen/Spirv.h"
#include "voxc/shaders/ShaderSources.h"

#include <string>
#include <vector>

namespace voxc::vulkan_detail {

namespace {

constexpr const char* kPassFiles[kMcPassCount] = {"mc_tiles.glsl", "mc_count.glsl", "mc_scan.glsl", "mc_compact.glsl",
                                                   "mc_vertices.glsl", "mc_triangles.glsl"};

// The pass's #version line, then the shared declarations, then the rest of the pass.
std::string passSource(const char* file) {
    const std::string pass(shaderSource(file));
    const size_t firstLine = pass.find('\n') + 1;
    return pass.substr(0, firstLine) + std::string(shaderSource("mc_common.glsl")) + pass.substr(firstLine);
}

} // namespace

void createMcPipelines(VulkanContext::Impl& ctx, McPipelines& out) {
    std::array<uint32_t, kMcBindingCount> bindings;
    for (uint32_t b = 0; b < kMcBindingCount; ++b) bindings[b] = b;
    createStorageSet(ctx, bindings, sizeof(McPush), out);
    for (uint32_t pass = 0; pass < kMcPassCount; ++pass) {
        const std::vector<uint32_t> spirv = codegen::compileComputeShader(kPassFiles[pass], passSource(kPassFiles[pass]));
        out.pipelines[pass] = createComputePipeline(ctx, out.layout, spirv, kPassFiles[pass]);
    }
}

void bindMcBuffers(VulkanContext::Impl& ctx, const McPipelines& pipelines, const std::array<VkBuffer, kMcBindingCount>& buffers,
                   uint32_t first, uint32_t last) {
    std::vector<uint32_t> bindings;
    for (uint32_t b = first; b < last; ++b) bindings.push_back(b);
    writeStorageBindings(ctx, pipelines.set, bindings, std::span(buffers).subspan(first, last - first));
}

void destroyMcPipelines(VulkanContext::Impl& ctx, McPipelines& pipelines) {
    for (VkPipeline& pipeline : pipelines.pipelines)
        if (pipeline) ctx.api.vkDestroyPipeline(ctx.device, pipeline, nullptr);
    destroyStorageSet(ctx, pipelines);
    pipelines = McPipelines{};
}

} // namespace voxc::vulkan_detail
