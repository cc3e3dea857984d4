#include "voxc/vulkan/SolveRunner.h"

#include "DeviceBuffer.h"
#include "CommandSlot.h"
#include "StorageSet.h"
#include "voxc/core/Errors.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstring>

namespace voxc {

using namespace vulkan_detail;

namespace {

// Every step reads what the one before wrote, in any of the buffers.
void computeBarrier(const VulkanApi& api, VkCommandBuffer cmd, VkPipelineStageFlags before, VkAccessFlags beforeAccess) {
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = beforeAccess;
    b.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT |
                      VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
    api.vkCmdPipelineBarrier(cmd, before,
                             VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT |
                                 VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                             0, 1, &b, 0, nullptr, 0, nullptr);
}

constexpr VkPipelineStageFlags kAllWork = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
constexpr VkAccessFlags kAllAccess =
    VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;

} // namespace

struct VulkanSolveRunner::Impl {
    VulkanContext::Impl& ctx;
    SolveProgram program;
    StorageSet set;
    std::vector<VkPipeline> pipelines;
    std::vector<DeviceBuffer> buffers;
    DeviceBuffer staging; // uploads, the measure word and the read-back words pass through it
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    double executeMs = 0;
    uint64_t dispatches = 0;

    Impl(VulkanContext::Impl& c, const SolveProgram& p) : ctx(c), program(p) {}
    ~Impl();

    void begin();
    void submitAndWait(); // ends, submits and waits for the command buffer
    void recordSteps(const std::vector<SolveStep>& steps);
    void upload(uint32_t buffer, const std::vector<uint32_t>& words);
    std::vector<uint32_t> download(uint32_t buffer, uint64_t words);
    float measure();
};

VulkanSolveRunner::Impl::~Impl() {
    if (ctx.device) ctx.api.vkDeviceWaitIdle(ctx.device);
    if (fence) ctx.api.vkDestroyFence(ctx.device, fence, nullptr);
    if (pool) ctx.api.vkDestroyCommandPool(ctx.device, pool, nullptr);
    destroyBuffer(ctx, staging);
    for (DeviceBuffer& b : buffers) destroyBuffer(ctx, b);
    for (VkPipeline p : pipelines)
        if (p) ctx.api.vkDestroyPipeline(ctx.device, p, nullptr);
    destroyStorageSet(ctx, set);
}

void VulkanSolveRunner::Impl::begin() {
    check(ctx.api.vkResetCommandBuffer(cmd, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(ctx.api.vkBeginCommandBuffer(cmd, &info), "vkBeginCommandBuffer");
}

void VulkanSolveRunner::Impl::submitAndWait() {
    // Device writes -> host reads of the staging buffer.
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = kAllAccess;
    b.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    ctx.api.vkCmdPipelineBarrier(cmd, kAllWork, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &b, 0, nullptr, 0, nullptr);
    check(ctx.api.vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    const auto start = std::chrono::steady_clock::now();
    check(ctx.api.vkQueueSubmit(ctx.queue, 1, &submit, fence), "vkQueueSubmit");
    check(ctx.api.vkWaitForFences(ctx.device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    check(ctx.api.vkResetFences(ctx.device, 1, &fence), "vkResetFences");
    executeMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void VulkanSolveRunner::Impl::recordSteps(const std::vector<SolveStep>& steps) {
    if (steps.empty()) return;
    ctx.api.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, set.layout, 0, 1, &set.set, 0, nullptr);
    uint32_t bound = UINT32_MAX;
    for (const SolveStep& step : steps) {
        computeBarrier(ctx.api, cmd, kAllWork, kAllAccess);
        if (step.kernel != bound) {
            ctx.api.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines.at(step.kernel));
            bound = step.kernel;
        }
        ctx.api.vkCmdPushConstants(cmd, set.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(step.push), step.push.data());
        if (step.indirect)
            ctx.api.vkCmdDispatchIndirect(cmd, buffers.at(step.indirectBuffer).buffer,
                                          VkDeviceSize(step.indirectWord) * sizeof(uint32_t));
        else
            ctx.api.vkCmdDispatch(cmd, step.groups[0], step.groups[1], step.groups[2]);
        ++dispatches;
    }
}

void VulkanSolveRunner::Impl::upload(uint32_t buffer, const std::vector<uint32_t>& words) {
    const VkDeviceSize bytes = std::min<VkDeviceSize>(words.size() * sizeof(uint32_t), buffers[buffer].size);
    begin();
    ctx.api.vkCmdFillBuffer(cmd, buffers[buffer].buffer, 0, VK_WHOLE_SIZE, 0);
    if (bytes > 0) {
        std::memcpy(staging.mapped, words.data(), bytes);
        flushForDevice(ctx, staging);
        computeBarrier(ctx.api, cmd, kAllWork, kAllAccess);
        const VkBufferCopy region{0, 0, bytes};
        ctx.api.vkCmdCopyBuffer(cmd, staging.buffer, buffers[buffer].buffer, 1, &region);
    }
    submitAndWait();
}

std::vector<uint32_t> VulkanSolveRunner::Impl::download(uint32_t buffer, uint64_t words) {
    const VkDeviceSize bytes = std::min<VkDeviceSize>(words * sizeof(uint32_t), buffers[buffer].size);
    begin();
    computeBarrier(ctx.api, cmd, kAllWork, kAllAccess);
    const VkBufferCopy region{0, 0, bytes};
    if (bytes > 0) ctx.api.vkCmdCopyBuffer(cmd, buffers[buffer].buffer, staging.buffer, 1, &region);
    submitAndWait();
    invalidateForHost(ctx, staging);
    std::vector<uint32_t> out(bytes / sizeof(uint32_t));
    std::memcpy(out.data(), staging.mapped, bytes);
    return out;
}

VulkanSolveRunner::VulkanSolveRunner(VulkanContext& context, const SolveProgram& program)
    : impl_(std::make_unique<Impl>(*context.impl_, program)) {
    Impl& s = *impl_;
    std::vector<uint32_t> bindings;
    for (uint32_t b = 0; b < program.bufferWords.size(); ++b) bindings.push_back(b);
    createStorageSet(s.ctx, bindings, sizeof(SolveStep::push), s.set);
    for (const Kernel& kernel : program.kernels)
        s.pipelines.push_back(createComputePipeline(s.ctx, s.set.layout, kernel.spirv, kernel.name));

    const uint64_t maxRange = s.ctx.properties.limits.maxStorageBufferRange;
    uint64_t stagingBytes = sizeof(uint32_t);
    std::vector<VkBuffer> handles;
    for (uint64_t words : program.bufferWords) {
        const uint64_t bytes = std::max<uint64_t>(words, 1) * sizeof(uint32_t);
        if (bytes > maxRange)
            throw UserError(fmt::format("a solve needs a {:.1f} MiB buffer, more than the Vulkan device '{}' can bind "
                                        "as one storage buffer ({:.1f} MiB); use a smaller solve box",
                                        double(bytes) / (1 << 20), s.ctx.info.name, double(maxRange) / (1 << 20)));
        s.buffers.push_back(createBuffer(s.ctx, bytes,
                                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                             VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                                         MemoryUse::Device));
        handles.push_back(s.buffers.back().buffer);
        stagingBytes = std::max(stagingBytes, bytes);
    }
    s.staging = createBuffer(s.ctx, stagingBytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                             MemoryUse::HostAccess);
    writeStorageBindings(s.ctx, s.set.set, bindings, handles);

    const CommandSlot slot = createCommandSlot(s.ctx);
    s.pool = slot.pool;
    s.cmd = slot.commands;
    s.fence = slot.fence;
}

VulkanSolveRunner::~VulkanSolveRunner() = default;

SolveRun VulkanSolveRunner::run(const std::vector<std::vector<uint32_t>>& initial, const std::vector<uint64_t>& readWords) {
    Impl& s = *impl_;
    const SolveProgram& p = s.program;
    s.executeMs = 0;
    s.dispatches = 0;
    for (uint32_t b = 0; b < s.buffers.size(); ++b) s.upload(b, b < initial.size() ? initial[b] : std::vector<uint32_t>{});

    SolveRun run;
    const bool counting = p.stop == SolveProgram::Stop::CountIsZero;
    const float tolerance = counting ? 0.0f : p.tolerance;
    // One submit per prologue and per cycle, each ending with the measure read back.
    const auto stepAndMeasure = [&](const std::vector<SolveStep>& steps) {
        s.begin();
        s.recordSteps(steps);
        computeBarrier(s.ctx.api, s.cmd, kAllWork, kAllAccess);
        const VkDeviceSize at = counting ? VkDeviceSize(p.measureWord) * sizeof(uint32_t) : 0;
        if (!counting) s.ctx.api.vkCmdFillBuffer(s.cmd, s.buffers.at(p.measureBuffer).buffer, 0, sizeof(uint32_t), 0);
        s.recordSteps(p.measure);
        computeBarrier(s.ctx.api, s.cmd, kAllWork, kAllAccess);
        const VkBufferCopy region{at, 0, sizeof(uint32_t)};
        s.ctx.api.vkCmdCopyBuffer(s.cmd, s.buffers.at(p.measureBuffer).buffer, s.staging.buffer, 1, &region);
        s.submitAndWait();
        invalidateForHost(s.ctx, s.staging);
        uint32_t word;
        std::memcpy(&word, s.staging.mapped, sizeof word);
        run.measures.push_back(counting ? float(word) : std::bit_cast<float>(word));
    };
    stepAndMeasure(p.prologue);
    while (!(run.measures.back() <= tolerance) && int32_t(run.measures.size()) - 1 < p.maxCycles)
        stepAndMeasure(p.cycle);
    run.converged = run.measures.back() <= tolerance;
    for (uint32_t b = 0; b < readWords.size() && b < s.buffers.size(); ++b)
        run.buffers.push_back(readWords[b] > 0 ? s.download(b, readWords[b]) : std::vector<uint32_t>{});
    run.executeMs = s.executeMs;
    run.dispatches = s.dispatches;
    return run;
}

} // namespace voxc
