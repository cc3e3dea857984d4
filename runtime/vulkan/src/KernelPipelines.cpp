#include "KernelPipelines.h"

#include <fmt/format.h>

#include <iterator>
#include <mutex>
#include <string>

namespace voxc::vulkan_detail {

namespace {

// Descriptor set 0 of every kernel (compiler/shaders/common.glsl), all storage buffers.
constexpr uint32_t kBindings[] = {kBindingVoxels,       kBindingChunkTable,   kBindingNoiseTables,
                                  kBindingTileRanges,  kBindingTileDirty,   kBindingActiveTiles,
                                  kBindingActiveDispatch, kBindingSkipStats,  kBindingMaterials,
                                  kBindingNonFinite,     kBindingPointSets,   kBindingScratch,
                                  kBindingSolveTables,   kBindingTileOccupancy};
static_assert(std::size(kBindings) == kKernelBindingCount);
constexpr uint32_t kBindingCount = std::size(kBindings);

std::string describe(const Kernel& kernel) { return fmt::format("kernel '{}' ({})", kernel.name, kernel.origin); }

// The context's pipeline of the kernel's SPIR-V, created the first time over the context's own
// layout (defined as every executor's), so it outlives the executor that asked first.
VkPipeline sharedPipeline(VulkanContext::Impl& ctx, const Kernel& kernel) {
    std::lock_guard lock(ctx.kernelPipelineMutex);
    if (const auto it = ctx.kernelPipelines.find(kernel.spirv); it != ctx.kernelPipelines.end()) {
        ++ctx.kernelPipelineCounts.shared;
        return it->second;
    }
    if (!ctx.kernelPipelineLayout)
        createStorageLayout(ctx, kBindings, sizeof(PushBlock), ctx.kernelSetLayout, ctx.kernelPipelineLayout);
    const VkPipeline pipeline = createComputePipeline(ctx, ctx.kernelPipelineLayout, kernel.spirv, describe(kernel));
    ctx.kernelPipelines.emplace(kernel.spirv, pipeline);
    ++ctx.kernelPipelineCounts.created;
    return pipeline;
}

} // namespace

void createPipelines(VulkanContext::Impl& ctx, const std::vector<Kernel>& kernels, KernelPipelines& out) {
    createStorageSet(ctx, kBindings, sizeof(PushBlock), out);
    out.shared = ctx.shareKernelPipelines;
    for (const Kernel& kernel : kernels) {
        if (out.shared) {
            out.pipelines.push_back(sharedPipeline(ctx, kernel));
            continue;
        }
        out.pipelines.push_back(createComputePipeline(ctx, out.layout, kernel.spirv, describe(kernel)));
        std::lock_guard lock(ctx.kernelPipelineMutex);
        ++ctx.kernelPipelineCounts.created;
    }
}

void bindBuffers(VulkanContext::Impl& ctx, const KernelPipelines& pipelines,
                 const std::array<VkBuffer, kKernelBindingCount>& byBinding) {
    std::array<VkBuffer, kBindingCount> buffers;
    for (uint32_t i = 0; i < kBindingCount; ++i) buffers[i] = byBinding[kBindings[i]];
    writeStorageBindings(ctx, pipelines.set, kBindings, buffers);
}

void destroyPipelines(VulkanContext::Impl& ctx, KernelPipelines& p) {
    if (!p.shared)
        for (VkPipeline pipeline : p.pipelines) ctx.api.vkDestroyPipeline(ctx.device, pipeline, nullptr);
    destroyStorageSet(ctx, p);
    p = KernelPipelines{};
}

} // namespace voxc::vulkan_detail
