#include "KernelPipelines.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <iterator>
#include <mutex>
#include <string>
#include <thread>

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

// Creates the pipeline of kernels[i] into out[i] for every i in `which`, on as many threads as
// the host has (up to one per kernel): the driver compiles a pipeline in the calling thread, and
// lavapipe spends about 30 ms of CPU on each even when its shader cache has the code, so a run's
// kernels took the longest part of its set-up one after another. Every pipeline that can be made
// is made; the first failure in `which` order is returned, for the caller to throw once it has
// accounted for the pipelines made.
std::exception_ptr createEach(VulkanContext::Impl& ctx, VkPipelineLayout layout, const std::vector<Kernel>& kernels,
                const std::vector<size_t>& which, std::vector<VkPipeline>& out) {
    std::vector<std::exception_ptr> failures(which.size());
    std::atomic<size_t> next{0};
    const auto work = [&] {
        for (size_t k; (k = next.fetch_add(1)) < which.size();) {
            const Kernel& kernel = kernels[which[k]];
            try {
                out[which[k]] = createComputePipeline(ctx, layout, kernel.spirv, describe(kernel));
            } catch (...) {
                failures[k] = std::current_exception();
            }
        }
    };
    const size_t threads = std::min<size_t>(which.size(), std::max(1u, std::thread::hardware_concurrency()));
    {
        std::vector<std::jthread> helpers;
        for (size_t t = 1; t < threads; ++t) helpers.emplace_back(work);
        work();
    }
    const auto failure =
        std::find_if(failures.begin(), failures.end(), [](const std::exception_ptr& f) { return bool(f); });
    return failure != failures.end() ? *failure : nullptr;
}

// Each kernel gets the context's pipeline of its SPIR-V, created over the context's own layout
// (defined as every executor's) where no earlier executor made one, so it outlives the executor
// that asked first. The new ones are created outside the lock; one that another executor made
// meanwhile is kept and ours destroyed.
void shareContextPipelines(VulkanContext::Impl& ctx, const std::vector<Kernel>& kernels, KernelPipelines& out) {
    std::vector<size_t> missing;            // the first kernel of each SPIR-V the context lacks
    std::vector<size_t> sameAs(kernels.size()); // the kernel whose pipeline kernel i takes
    {
        std::lock_guard lock(ctx.kernelPipelineMutex);
        if (!ctx.kernelPipelineLayout)
            createStorageLayout(ctx, kBindings, sizeof(PushBlock), ctx.kernelSetLayout, ctx.kernelPipelineLayout);
        for (size_t i = 0; i < kernels.size(); ++i) {
            sameAs[i] = i;
            if (const auto it = ctx.kernelPipelines.find(kernels[i].spirv); it != ctx.kernelPipelines.end()) {
                out.pipelines[i] = it->second;
                ++ctx.kernelPipelineCounts.shared;
                continue;
            }
            const auto earlier = std::find_if(missing.begin(), missing.end(),
                                              [&](size_t j) { return kernels[j].spirv == kernels[i].spirv; });
            if (earlier != missing.end()) sameAs[i] = *earlier;
            else missing.push_back(i);
        }
    }
    const std::exception_ptr failure = createEach(ctx, ctx.kernelPipelineLayout, kernels, missing, out.pipelines);
    {
        // Made pipelines go to the context even after a failure: it destroys them, not `out`.
        std::lock_guard lock(ctx.kernelPipelineMutex);
        for (const size_t i : missing) {
            if (!out.pipelines[i]) continue;
            const auto [it, added] = ctx.kernelPipelines.emplace(kernels[i].spirv, out.pipelines[i]);
            if (added) {
                ++ctx.kernelPipelineCounts.created;
            } else {
                ctx.api.vkDestroyPipeline(ctx.device, out.pipelines[i], nullptr);
                out.pipelines[i] = it->second;
                ++ctx.kernelPipelineCounts.shared;
            }
        }
        for (size_t i = 0; i < kernels.size(); ++i)
            if (sameAs[i] != i && out.pipelines[sameAs[i]]) {
                out.pipelines[i] = out.pipelines[sameAs[i]];
                ++ctx.kernelPipelineCounts.shared;
            }
    }
    if (failure) std::rethrow_exception(failure);
}

} // namespace

void createPipelines(VulkanContext::Impl& ctx, const std::vector<Kernel>& kernels, KernelPipelines& out) {
    createStorageSet(ctx, kBindings, sizeof(PushBlock), out);
    out.shared = ctx.shareKernelPipelines;
    out.pipelines.assign(kernels.size(), VK_NULL_HANDLE);
    if (out.shared) {
        shareContextPipelines(ctx, kernels, out);
        return;
    }
    std::vector<size_t> all(kernels.size());
    for (size_t i = 0; i < all.size(); ++i) all[i] = i;
    const std::exception_ptr failure = createEach(ctx, out.layout, kernels, all, out.pipelines);
    {
        std::lock_guard lock(ctx.kernelPipelineMutex);
        ctx.kernelPipelineCounts.created += size_t(
            std::count_if(out.pipelines.begin(), out.pipelines.end(), [](VkPipeline p) { return p != VK_NULL_HANDLE; }));
    }
    if (failure) std::rethrow_exception(failure);
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
