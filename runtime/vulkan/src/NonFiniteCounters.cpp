#include "NonFiniteCounters.h"

#include "voxc/codegen/KernelPackage.h"
#include "voxc/core/Errors.h"

#include <algorithm>

namespace voxc::vulkan_detail {

namespace {
// nonfinite.glsl's NonFinite block: count low, count high, lowest grid index.
constexpr VkDeviceSize kCounterBytes = 3 * sizeof(uint32_t);
} // namespace

void NonFiniteCounters::create(VulkanContext::Impl& ctx, size_t stageCount, MemoryUse counterMemory) {
    stageCount_ = stageCount;
    counter_ = createBuffer(ctx, kCounterBytes,
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            counterMemory);
    byStage_ = createBuffer(ctx, std::max<VkDeviceSize>(1, stageCount) * kCounterBytes,
                            VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::HostAccess);
}

void NonFiniteCounters::destroy(VulkanContext::Impl& ctx) {
    destroyBuffer(ctx, byStage_);
    destroyBuffer(ctx, counter_);
}

void NonFiniteCounters::recordReset(VulkanContext::Impl& ctx, VkCommandBuffer cmd) const {
    ctx.api.vkCmdFillBuffer(cmd, counter_.buffer, 0, 2 * sizeof(uint32_t), 0);
    ctx.api.vkCmdFillBuffer(cmd, counter_.buffer, 2 * sizeof(uint32_t), sizeof(uint32_t), 0xFFFFFFFFu);
}

void NonFiniteCounters::recordRunStart(VulkanContext::Impl& ctx, VkCommandBuffer cmd) const {
    ctx.api.vkCmdFillBuffer(cmd, byStage_.buffer, 0, VK_WHOLE_SIZE, 0);
    recordReset(ctx, cmd);
}

void NonFiniteCounters::recordStageEnd(VulkanContext::Impl& ctx, VkCommandBuffer cmd, uint32_t stage) const {
    VOXC_ASSERT(stage < stageCount_);
    const VkBufferCopy region{0, VkDeviceSize(stage) * kCounterBytes, kCounterBytes};
    ctx.api.vkCmdCopyBuffer(cmd, counter_.buffer, byStage_.buffer, 1, &region);
    // The reset must not overtake the copy's read.
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    ctx.api.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &b, 0,
                                 nullptr, 0, nullptr);
    recordReset(ctx, cmd);
}

std::vector<NonFiniteCount> NonFiniteCounters::read(VulkanContext::Impl& ctx) const {
    invalidateForHost(ctx, byStage_);
    std::vector<NonFiniteCount> counts(stageCount_);
    const auto* words = static_cast<const uint32_t*>(byStage_.mapped);
    for (size_t i = 0; i < counts.size(); ++i) {
        counts[i].count = uint64_t(words[3 * i]) | uint64_t(words[3 * i + 1]) << 32;
        counts[i].firstIndex = counts[i].count ? words[3 * i + 2] : 0;
    }
    return counts;
}

} // namespace voxc::vulkan_detail
