#include "KernelPipelines.h"


#include <fmt/format.h>

#include <iterator>

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

} // namespace

void createPipelines(VulkanContext::Impl& ctx, const std::vector<Kernel>& kernels, KernelPipelines& out) {
    createStorageSet(ctx, kBindings, sizeof(PushBlock), out);
    for (const Kernel& kernel : kernels)
        out.pipelines.push_back(
            createComputePipeline(ctx, out.layout, kernel.spirv, fmt::format("kernel '{}' ({})", kernel.name, kernel.origin)));
}

void bindBuffers(VulkanContext::Impl& ctx, const KernelPipelines& pipelines,
                 const std::array<VkBuffer, kKernelBindingCount>& byBinding) {
    std::array<VkBuffer, kBindingCount> buffers;
    for (uint32_t i = 0; i < kBindingCount; ++i) buffers[i] = byBinding[kBindings[i]];
    writeStorageBindings(ctx, pipelines.set, kBindings, buffers);
}

void destroyPipelines(VulkanContext::Impl& ctx, KernelPipelines& p) {
    for (VkPipeline pipeline : p.pipelines) ctx.api.vkDestroyPipeline(ctx.device, pipeline, nullptr);
    destroyStorageSet(ctx, p);
    p = KernelPipelines{};
}

} // namespace voxc::vulkan_detail
