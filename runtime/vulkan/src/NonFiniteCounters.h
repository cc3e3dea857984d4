#pragma once
// The non-finite counters of a run (kBindingNonFinite; compiler/shaders/nonfinite.glsl): the
// field and sweep kernels count the current stage's replacements into one small buffer, which
// is copied into a host-visible slot per package stage where the stage's dispatches end, then
// reset. So a run reads every stage's counts at its end without waiting on the device between
// stages.
#include "ContextImpl.h"
#include "DeviceBuffer.h"
#include "voxc/grid/NonFinite.h"

#include <vector>

namespace voxc::vulkan_detail {

class NonFiniteCounters {
public:
    // `counterMemory`: where the kernels' counter lives (Device on discrete GPUs).
    void create(VulkanContext::Impl& ctx, size_t stageCount, MemoryUse counterMemory);
    void destroy(VulkanContext::Impl& ctx);
    VkBuffer counterBuffer() const { return counter_.buffer; }

    // Every stage's slot 0 (a stage without dispatches keeps it) and the counter reset; transfer
    // commands, to be followed by a barrier before the first kernel.
    void recordRunStart(VulkanContext::Impl& ctx, VkCommandBuffer cmd) const;
    // Copies the counter into `stage`'s slot and resets it. Transfer commands: the caller puts a
    // barrier from the stage's kernels before and one to the next kernels after.
    void recordStageEnd(VulkanContext::Impl& ctx, VkCommandBuffer cmd, uint32_t stage) const;
    // After the run's last command buffer has completed (and a barrier to host reads).
    std::vector<NonFiniteCount> read(VulkanContext::Impl& ctx) const;

private:
    void recordReset(VulkanContext::Impl& ctx, VkCommandBuffer cmd) const;

    size_t stageCount_ = 0;
    DeviceBuffer counter_, byStage_;
};

} // namespace voxc::vulkan_detail
