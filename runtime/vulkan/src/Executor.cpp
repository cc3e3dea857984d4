#include "voxc/vulkan/Executor.h"

#include "ContextImpl.h"
#include "DeviceBuffer.h"
#include "ExecutorVoxels.h"
#include "KernelPipelines.h"
#include "NonFiniteCounters.h"
#include "voxc/builtins/Shapes.h"
#include "voxc/core/Errors.h"
#include "voxc/vulkan/DispatchPlan.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <functional>
#include <optional>
#include <span>
#include <utility>

namespace voxc {

using namespace vulkan_detail;

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Every command touches the voxel buffer or the tile buffers, so each waits on the last; an
// indirect dispatch also reads its arguments, written by the active-tiles kernel before it.
struct Access {
    VkPipelineStageFlags stage;
    VkAccessFlags access;
};
constexpr Access kTransferRead{VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT};
constexpr Access kTransferWrite{VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT};
constexpr Access kTransferReadWrite{VK_PIPELINE_STAGE_TRANSFER_BIT,
                                    VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT};
constexpr Access kCompute{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                          VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT};
constexpr Access kShaderRead{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT};
constexpr Access kHostRead{VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT};

void barrier(const VulkanApi& api, VkCommandBuffer cmd, VkBuffer buffer, Access before, Access after) {
    VkBufferMemoryBarrier b{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    b.srcAccessMask = before.access;
    b.dstAccessMask = after.access;
    b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.buffer = buffer;
    b.size = VK_WHOLE_SIZE;
    api.vkCmdPipelineBarrier(cmd, before.stage, after.stage, 0, 0, nullptr, 1, &b, 0, nullptr);
}

// Over every buffer: the voxels and the tile buffers change hands between commands together.
void memoryBarrier(const VulkanApi& api, VkCommandBuffer cmd, Access before, Access after) {
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = before.access;
    b.dstAccessMask = after.access;
    api.vkCmdPipelineBarrier(cmd, before.stage, after.stage, 0, 1, &b, 0, nullptr, 0, nullptr);
}

} // namespace

struct VulkanExecutor::Impl {
    struct Frame {
        VkCommandBuffer cmd = VK_NULL_HANDLE;
        VkFence fence = VK_NULL_HANDLE;
        bool pending = false;
        uint32_t dispatches = 0; // in the batch last submitted
    };

    VulkanContext::Impl& ctx;
    KernelPackage package;
    ExecutorOptions options;
    ChunkLayout layout;
    std::array<uint32_t, 3> maxGroups{};
    bool staged = false; // results come back through `readback` instead of a mapped voxel buffer
    bool clearsVoxels = true; // false: the first stage writes every voxel of the buffer (firstStageFillsBuffer)
    int32_t tileShift = -1; // >= 0: sweeps run over active tiles only (DispatchCursor)
    KernelPipelines pipelines;
    // `materials` is one uint per voxel beside `voxels` when the package uses materials, else a
    // one-element buffer no kernel declares; `readback` holds the densities, then the materials.
    DeviceBuffer voxels, materials, chunkTable, noiseTables, readback;
    DeviceBuffer pointSets; // kBindingPointSets: package.pointSets with their per-cell lists
    DeviceBuffer solveTables; // kBindingSolveTables: package.solveTables (solveTableWords)
    DeviceBuffer scratch;   // kBindingScratch: the largest StagePlan::scratchWords (at least one word)
    // Tile skipping (kBindingTileRanges..kBindingSkipStats); small, so they exist either way.
    DeviceBuffer tileRanges, tileDirty, activeTiles, activeDispatch, skipStats, tileOccupancy;
    NonFiniteCounters nonFinite; // kBindingNonFinite and its per-stage copies
    bool hasRun = false;         // the voxel buffer holds a run's result
    std::optional<TileRanges> readBackRanges; // of the voxel buffer, where the last run read it back
    VkCommandPool commandPool = VK_NULL_HANDLE;
    Frame frames[2];
    double setupMs = 0;

    Impl(VulkanContext::Impl& c, const KernelPackage& p, const ExecutorOptions& o) : ctx(c), package(p), options(o) {}
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    ~Impl();

    void checkLimits() const;
    // The first stage writes every voxel's density, reading none, and no chunk has padding voxels
    // outside the grid, so clearing the voxel buffer before it would only cost a pass over it.
    bool firstStageFillsBuffer() const;
    void createBuffers();
    // A read-only int buffer with `values`, ready for every kernel.
    DeviceBuffer createTable(const std::vector<int32_t>& values);
    // The same with `words` words that `fill` writes, straight into the mapped memory (no copy
    // of a large table on the host).
    DeviceBuffer createTable(size_t words, const std::function<void(std::span<int32_t>)>& fill);
    // The words of kBindingPointSets (a UserError naming the bound when the lists outgrow it).
    std::vector<int32_t> pointSetTable() const;
    void createFrames();
    void submit(Frame& frame);
    void wait(Frame& frame);
    void recordReadback(VkCommandBuffer cmd, Access last);
    void readMaterials(const DeviceBuffer& source, VkDeviceSize offset, ChunkedGrid& grid) const;
    // Every tile range stale, no active-dispatch record in use, statistics zero.
    void recordTileReset(VkCommandBuffer cmd);
    // Copies the non-finite counts of package stage `stage` out and resets them for the next stage.
    void recordStageEnd(VkCommandBuffer cmd, uint32_t stage, Access& last);
};

VulkanExecutor::Impl::~Impl() {
    if (ctx.device) ctx.api.vkDeviceWaitIdle(ctx.device);
    for (Frame& frame : frames)
        if (frame.fence) ctx.api.vkDestroyFence(ctx.device, frame.fence, nullptr);
    if (commandPool) ctx.api.vkDestroyCommandPool(ctx.device, commandPool, nullptr);
    nonFinite.destroy(ctx);
    for (DeviceBuffer* b : {&tileOccupancy, &skipStats, &activeDispatch, &activeTiles, &tileDirty, &tileRanges})
        destroyBuffer(ctx, *b);
    destroyBuffer(ctx, readback);
    destroyBuffer(ctx, pointSets);
    destroyBuffer(ctx, solveTables);
    destroyBuffer(ctx, scratch);
    destroyBuffer(ctx, noiseTables);
    destroyBuffer(ctx, chunkTable);
    destroyBuffer(ctx, materials);
    destroyBuffer(ctx, voxels);
    destroyPipelines(ctx, pipelines);
}

// The material buffer has a uint per voxel, as many bytes as the voxel buffer, so one check covers both.
void VulkanExecutor::Impl::checkLimits() const {
    static_assert(sizeof(uint32_t) == sizeof(float));
    const uint64_t bytes = uint64_t(layout.chunkTotal()) * layout.chunkVoxels() * sizeof(float);
    const uint64_t maxRange = ctx.properties.limits.maxStorageBufferRange;
    uint64_t tableWords = 1 + package.solveTables.size();
    for (const auto& table : package.solveTables)
        tableWords += 6 + table->cellCount() * (table->material.empty() ? 1 : 2);
    if (tableWords * sizeof(int32_t) > maxRange)
        throw UserError(fmt::format("the curves' solve tables need {:.1f} MiB, more than the Vulkan device '{}' can "
                                    "bind as one storage buffer ({:.1f} MiB); use smaller curves boxes",
                                    double(tableWords * sizeof(int32_t)) / (1 << 20), ctx.info.name,
                                    double(maxRange) / (1 << 20)));
    if (bytes > maxRange)
        throw UserError(fmt::format("the grid needs a {:.1f} MiB voxel buffer ({} chunks of {}^3 voxels), more than "
                                    "the Vulkan device '{}' can bind as one storage buffer ({:.1f} MiB); run a box of "
                                    "the world with --region, or the whole world in tiles with `voxc world`",
                                    double(bytes) / (1 << 20), layout.chunkTotal(), layout.chunkSize, ctx.info.name,
                                    double(maxRange) / (1 << 20)));
}

bool VulkanExecutor::Impl::firstStageFillsBuffer() const {
    const glm::ivec3 size = layout.gridSize;
    const bool noPadding = layout.chunkTotal() * layout.chunkVoxels() == size_t(size.x) * size_t(size.y) * size_t(size.z);
    return noPadding && !package.stages.empty() && package.stages.front().writesEveryDensity;
}

void VulkanExecutor::Impl::createBuffers() {
    const VkDeviceSize voxelBytes = VkDeviceSize(layout.chunkTotal()) * layout.chunkVoxels() * sizeof(float);
    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    // The device mesher also reads the densities and materials as uniform texel buffers (GpuMesher.cpp).
    const VkBufferUsageFlags voxelUsage = storage | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
    voxels = staged ? createBuffer(ctx, voxelBytes, voxelUsage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Device)
                    : createBuffer(ctx, voxelBytes, voxelUsage, MemoryUse::HostAccess);
    const VkDeviceSize materialBytes = package.usesMaterials ? voxelBytes : sizeof(uint32_t);
    materials = staged ? createBuffer(ctx, materialBytes, voxelUsage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Device)
                       : createBuffer(ctx, materialBytes, voxelUsage, MemoryUse::HostAccess);
    if (staged)
        readback = createBuffer(ctx, voxelBytes + (package.usesMaterials ? materialBytes : 0),
                                VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::HostAccess);
    const std::vector<int32_t> table = layout.chunkTable();
    chunkTable = createTable(table);
    const std::span<const int, 256> permutation = perlinPermutation();
    noiseTables = createTable(std::vector<int32_t>(permutation.begin(), permutation.end()));
    pointSets = createTable(pointSetTable());
    solveTables = createTable(solveTableWordCount(package.solveTables),
                              [&](std::span<int32_t> out) { writeSolveTableWords(package.solveTables, out); });
    uint64_t scratchWords = 1;
    for (const StagePlan& stage : package.stages) scratchWords = std::max(scratchWords, stage.scratchWords);
    scratch = createBuffer(ctx, VkDeviceSize(scratchWords) * sizeof(uint32_t), storage,
                           staged ? MemoryUse::Device : MemoryUse::HostAccess);

    const VkDeviceSize tiles = tileShift >= 0 ? tileCount(package, tileShift) : 1;
    const MemoryUse local = staged ? MemoryUse::Device : MemoryUse::HostAccess;
    tileRanges = createBuffer(ctx, tiles * 2 * sizeof(uint32_t), storage, local);
    tileDirty = createBuffer(ctx, tiles * sizeof(uint32_t), storage, local);
    activeTiles = createBuffer(ctx, tiles * sizeof(uint32_t), storage, local);
    activeDispatch = createBuffer(ctx, 8 * sizeof(uint32_t), storage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, local);
    skipStats = createBuffer(ctx, sizeof(uint32_t), storage, MemoryUse::HostAccess);
    // A bit per voxel where tiles keep occupancy (tiles.glsl occupancyTracked); tile_ranges sets every word.
    const VkDeviceSize occupancyWords = tileShift >= 3 && tileShift <= 4 ? tiles << (3 * tileShift - 5) : 1;
    tileOccupancy = createBuffer(ctx, occupancyWords * sizeof(uint32_t), storage, local);
    nonFinite.create(ctx, package.stages.size(), local);
}

std::vector<int32_t> VulkanExecutor::Impl::pointSetTable() const {
    try {
        return pointSetWords(package.pointSets, layout.gridOrigin, layout.gridSize);
    } catch (const PointSetLimitError& e) {
        throw UserError(fmt::format("the point sets' per-cell lists would need more than {} {} (at least {}); "
                                    "use a smaller radius or fewer points",
                                    e.cap,
                                    std::string_view(e.limit) == "perCell" ? "entries in one cell's list"
                                                                           : "list entries, cell tests or words",
                                    e.amount));
    }
}

void VulkanExecutor::Impl::recordStageEnd(VkCommandBuffer cmd, uint32_t stage, Access& last) {
    memoryBarrier(ctx.api, cmd, last, kTransferReadWrite);
    nonFinite.recordStageEnd(ctx, cmd, stage);
    last = kTransferWrite;
}

void VulkanExecutor::Impl::recordTileReset(VkCommandBuffer cmd) {
    ctx.api.vkCmdFillBuffer(cmd, tileDirty.buffer, 0, VK_WHOLE_SIZE, 1);
    ctx.api.vkCmdFillBuffer(cmd, activeDispatch.buffer, 0, VK_WHOLE_SIZE, 0);
    ctx.api.vkCmdFillBuffer(cmd, skipStats.buffer, 0, VK_WHOLE_SIZE, 0);
}

DeviceBuffer VulkanExecutor::Impl::createTable(const std::vector<int32_t>& values) {
    return createTable(values.size(), [&](std::span<int32_t> out) { std::copy(values.begin(), values.end(), out.begin()); });
}

DeviceBuffer VulkanExecutor::Impl::createTable(size_t words, const std::function<void(std::span<int32_t>)>& fill) {
    const VkDeviceSize bytes = words * sizeof(int32_t);
    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    if (!staged) {
        DeviceBuffer table = createBuffer(ctx, bytes, storage, MemoryUse::HostAccess);
        fill({static_cast<int32_t*>(table.mapped), words});
        flushForDevice(ctx, table); // the queue submit then makes the host write visible
        return table;
    }
    DeviceBuffer table = createBuffer(ctx, bytes, storage, MemoryUse::Device);
    DeviceBuffer upload{};
    try {
        upload = createBuffer(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::HostAccess);
        fill({static_cast<int32_t*>(upload.mapped), words});
        flushForDevice(ctx, upload);
        Frame& frame = frames[0];
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        check(ctx.api.vkResetCommandBuffer(frame.cmd, 0), "vkResetCommandBuffer");
        check(ctx.api.vkBeginCommandBuffer(frame.cmd, &begin), "vkBeginCommandBuffer");
        const VkBufferCopy region{0, 0, bytes};
        ctx.api.vkCmdCopyBuffer(frame.cmd, upload.buffer, table.buffer, 1, &region);
        // Its second scope covers later submissions too, so every kernel sees the table.
        barrier(ctx.api, frame.cmd, table.buffer, kTransferWrite, kShaderRead);
        check(ctx.api.vkEndCommandBuffer(frame.cmd), "vkEndCommandBuffer");
        submit(frame);
        wait(frame);
    } catch (...) {
        destroyBuffer(ctx, upload);
        destroyBuffer(ctx, table);
        throw;
    }
    destroyBuffer(ctx, upload);
    return table;
}

void VulkanExecutor::Impl::createFrames() {
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = ctx.queueFamily;
    check(ctx.api.vkCreateCommandPool(ctx.device, &poolInfo, nullptr, &commandPool), "vkCreateCommandPool");
    for (Frame& frame : frames) {
        VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        allocate.commandPool = commandPool;
        allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        allocate.commandBufferCount = 1;
        check(ctx.api.vkAllocateCommandBuffers(ctx.device, &allocate, &frame.cmd), "vkAllocateCommandBuffers");
        VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        check(ctx.api.vkCreateFence(ctx.device, &fenceInfo, nullptr, &frame.fence), "vkCreateFence");
    }
}

void VulkanExecutor::Impl::submit(Frame& frame) {
    VkSubmitInfo info{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    info.commandBufferCount = 1;
    info.pCommandBuffers = &frame.cmd;
    check(ctx.api.vkQueueSubmit(ctx.queue, 1, &info, frame.fence), "vkQueueSubmit");
    frame.pending = true;
}

void VulkanExecutor::Impl::wait(Frame& frame) {
    if (!frame.pending) return;
    check(ctx.api.vkWaitForFences(ctx.device, 1, &frame.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    check(ctx.api.vkResetFences(ctx.device, 1, &frame.fence), "vkResetFences");
    frame.pending = false;
}

void VulkanExecutor::Impl::recordReadback(VkCommandBuffer cmd, Access last) {
    if (!staged) {
        barrier(ctx.api, cmd, voxels.buffer, last, kHostRead);
        if (package.usesMaterials) barrier(ctx.api, cmd, materials.buffer, last, kHostRead);
        return;
    }
    barrier(ctx.api, cmd, voxels.buffer, last, kTransferRead);
    const VkBufferCopy region{0, 0, voxels.size};
    ctx.api.vkCmdCopyBuffer(cmd, voxels.buffer, readback.buffer, 1, &region);
    if (package.usesMaterials) {
        barrier(ctx.api, cmd, materials.buffer, last, kTransferRead);
        const VkBufferCopy materialRegion{0, voxels.size, materials.size};
        ctx.api.vkCmdCopyBuffer(cmd, materials.buffer, readback.buffer, 1, &materialRegion);
    }
    barrier(ctx.api, cmd, readback.buffer, kTransferWrite, kHostRead);
}

// The device's uint ids (0..255, the kernels write nothing larger) into the grid's bytes.
void VulkanExecutor::Impl::readMaterials(const DeviceBuffer& source, VkDeviceSize offset, ChunkedGrid& grid) const {
    std::vector<uint8_t>& out = grid.materials();
    VOXC_ASSERT(out.size() * sizeof(uint32_t) == materials.size && offset + materials.size <= source.size);
    const auto* ids = reinterpret_cast<const uint32_t*>(static_cast<const char*>(source.mapped) + offset);
    for (size_t i = 0; i < out.size(); ++i) out[i] = uint8_t(ids[i]);
}

VulkanExecutor::VulkanExecutor(VulkanContext& context, const KernelPackage& package, const ExecutorOptions& options)
    : impl_(std::make_unique<Impl>(*context.impl_, package, options)) {
    const Clock::time_point start = Clock::now();
    Impl& s = *impl_;
    validatePackage(s.package);
    const World& world = s.package.world;
    s.layout = ChunkLayout::make(world.origin, world.size, world.chunkSize);
    s.checkLimits();
    for (int a = 0; a < 3; ++a) {
        const uint32_t device = s.ctx.properties.limits.maxComputeWorkGroupCount[a];
        s.maxGroups[a] = options.maxWorkGroups[a] ? std::min(options.maxWorkGroups[a], device) : device;
    }
    const DeviceType type = s.ctx.info.type;
    s.staged = options.alwaysStage || !(type == DeviceType::Integrated || type == DeviceType::Cpu);
    s.clearsVoxels = !s.firstStageFillsBuffer();
    if (s.options.dispatchesPerBatch == 0) s.options.dispatchesPerBatch = 1;
    s.tileShift = options.skipInactiveTiles ? skipTileShift(s.package, s.maxGroups) : -1;

    createPipelines(s.ctx, s.package.kernels, s.pipelines);
    s.createFrames();
    s.createBuffers();
    std::array<VkBuffer, kKernelBindingCount> byBinding{};
    byBinding[kBindingVoxels] = s.voxels.buffer;
    byBinding[kBindingChunkTable] = s.chunkTable.buffer;
    byBinding[kBindingNoiseTables] = s.noiseTables.buffer;
    byBinding[kBindingTileRanges] = s.tileRanges.buffer;
    byBinding[kBindingTileDirty] = s.tileDirty.buffer;
    byBinding[kBindingActiveTiles] = s.activeTiles.buffer;
    byBinding[kBindingActiveDispatch] = s.activeDispatch.buffer;
    byBinding[kBindingSkipStats] = s.skipStats.buffer;
    byBinding[kBindingTileOccupancy] = s.tileOccupancy.buffer;
    byBinding[kBindingMaterials] = s.materials.buffer;
    byBinding[kBindingNonFinite] = s.nonFinite.counterBuffer();
    byBinding[kBindingPointSets] = s.pointSets.buffer;
    byBinding[kBindingSolveTables] = s.solveTables.buffer;
    byBinding[kBindingScratch] = s.scratch.buffer;
    bindBuffers(s.ctx, s.pipelines, byBinding);
    s.setupMs = millisecondsSince(start);
}

VulkanExecutor::~VulkanExecutor() = default;

const ChunkLayout& VulkanExecutor::layout() const { return impl_->layout; }

double VulkanExecutor::setupMs() const { return impl_->setupMs; }

vulkan_detail::ExecutorVoxels VulkanExecutor::deviceVoxels() const {
    const Impl& s = *impl_;
    const DeviceBuffer* mapped = !s.staged && s.package.usesMaterials && s.materials.mapped ? &s.materials : nullptr;
    return {&s.ctx, s.voxels.buffer, s.materials.buffer, s.package.usesMaterials, s.hasRun, &s.readBackRanges, mapped};
}

RunResult VulkanExecutor::run() {
    Impl& s = *impl_;
    const VulkanApi& api = s.ctx.api;
    RunResult result{ChunkedGrid(s.options.readBack ? s.layout : ChunkLayout{}), {}, 0};
    s.readBackRanges.reset(); // the voxel buffer changes from here on
    result.timings.setupMs = s.setupMs;

    DispatchCursor cursor(s.package, s.maxGroups, s.tileShift);
    Dispatch next;
    bool more = cursor.next(next);
    Access last{};
    constexpr uint32_t kNoStage = UINT32_MAX;
    uint32_t stage = kNoStage; // the package stage whose dispatches are being recorded
    Clock::time_point executeStart;
    const uint32_t maxBatch = s.options.dispatchesPerBatch;
    const bool timedBatches = s.options.batchMilliseconds > 0;
    uint32_t batchSize = timedBatches ? std::min(16u, maxBatch) : maxBatch;
    std::optional<Clock::time_point> lastFinished; // when the batch before the one waited for finished
    for (uint32_t batch = 0;; ++batch) {
        Impl::Frame& frame = s.frames[batch % 2];
        const bool waits = frame.pending;
        s.wait(frame); // the batch before the previous one; the previous may still run meanwhile
        if (timedBatches && waits) {
            // The device ran the two batches back to back (or the host recorded the next one
            // meanwhile): the time between them finishing is the waited batch's.
            const Clock::time_point now = Clock::now();
            if (lastFinished) {
                const double ms = std::max(1e-3, std::chrono::duration<double, std::milli>(now - *lastFinished).count());
                const double wanted = double(frame.dispatches) * s.options.batchMilliseconds / ms;
                batchSize = uint32_t(std::clamp(wanted, std::max(1.0, batchSize / 2.0), std::min(double(maxBatch), batchSize * 2.0)));
            }
            lastFinished = now;
        }
        if (s.options.progress) {
            try {
                s.options.progress(double(stage == kNoStage ? 0 : stage) / double(std::max<size_t>(1, s.package.stages.size())));
            } catch (...) {
                s.wait(s.frames[0]);
                s.wait(s.frames[1]);
                throw;
            }
        }
        const Clock::time_point recordStart = Clock::now();
        check(api.vkResetCommandBuffer(frame.cmd, 0), "vkResetCommandBuffer");
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        check(api.vkBeginCommandBuffer(frame.cmd, &begin), "vkBeginCommandBuffer");
        if (batch == 0) {
            // Padding voxels outside the grid and grids without a start stage read as 0 on every run.
            if (s.clearsVoxels) api.vkCmdFillBuffer(frame.cmd, s.voxels.buffer, 0, VK_WHOLE_SIZE, 0);
            api.vkCmdFillBuffer(frame.cmd, s.materials.buffer, 0, VK_WHOLE_SIZE, 0); // every voxel `none`
            if (s.tileShift >= 0) s.recordTileReset(frame.cmd);
            s.nonFinite.recordRunStart(s.ctx, frame.cmd);
            last = kTransferWrite;
        }
        api.vkCmdBindDescriptorSets(frame.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, s.pipelines.layout, 0, 1,
                                    &s.pipelines.set, 0, nullptr);
        uint32_t bound = UINT32_MAX;
        uint32_t n = 0;
        for (; more && n < batchSize; ++n) {
            if (next.stage != stage) {
                if (stage != kNoStage) s.recordStageEnd(frame.cmd, stage, last);
                stage = next.stage;
            }
            if (next.kind == DispatchKind::InvalidateRanges) {
                memoryBarrier(api, frame.cmd, last, kTransferWrite);
                api.vkCmdFillBuffer(frame.cmd, s.tileDirty.buffer, 0, VK_WHOLE_SIZE, 1);
                last = kTransferWrite;
                more = cursor.next(next);
                continue;
            }
            memoryBarrier(api, frame.cmd, last, kCompute);
            last = kCompute;
            if (next.kernel != bound) {
                api.vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, s.pipelines.pipelines[next.kernel]);
                bound = next.kernel;
            }
            api.vkCmdPushConstants(frame.cmd, s.pipelines.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(PushBlock),
                                   &next.push);
            if (next.kind == DispatchKind::Indirect) {
                api.vkCmdDispatchIndirect(frame.cmd, s.activeDispatch.buffer,
                                          VkDeviceSize(next.record) * 4 * sizeof(uint32_t));
            } else {
                api.vkCmdDispatch(frame.cmd, next.groups[0], next.groups[1], next.groups[2]);
            }
            ++result.dispatches;
            more = cursor.next(next);
        }
        if (!more) {
            if (stage != kNoStage) s.recordStageEnd(frame.cmd, stage, last);
            memoryBarrier(api, frame.cmd, last, kHostRead); // the skip statistics and non-finite counts
            if (s.options.readBack) s.recordReadback(frame.cmd, last);
        }
        check(api.vkEndCommandBuffer(frame.cmd), "vkEndCommandBuffer");
        result.timings.recordMs += millisecondsSince(recordStart);
        if (batch == 0) executeStart = Clock::now();
        frame.dispatches = n;
        s.submit(frame);
        if (!more) break;
    }
    s.wait(s.frames[0]);
    s.wait(s.frames[1]);
    result.timings.executeMs = millisecondsSince(executeStart);

    if (s.options.readBack) {
        const Clock::time_point readStart = Clock::now();
        const DeviceBuffer& source = s.staged ? s.readback : s.voxels;
        invalidateForHost(s.ctx, source);
        const VkDeviceSize voxelBytes = s.voxels.size;
        VOXC_ASSERT(result.grid.data().size() * sizeof(float) == voxelBytes && voxelBytes <= source.size);
        // The copy records the grid's tile ranges on the way, for the meshers (the device one
        // keeps them: they describe the voxel buffer until the next run).
        result.grid.loadDensities(static_cast<const float*>(source.mapped));
        s.readBackRanges = *std::as_const(result.grid).tileRanges();
        if (s.package.usesMaterials) {
            if (!s.staged) invalidateForHost(s.ctx, s.materials);
            s.readMaterials(s.staged ? s.readback : s.materials, s.staged ? voxelBytes : 0, result.grid);
        }
        result.timings.readbackMs = millisecondsSince(readStart);
    }
    if (s.tileShift >= 0) {
        invalidateForHost(s.ctx, s.skipStats);
        uint32_t active = 0;
        std::memcpy(&active, s.skipStats.mapped, sizeof active);
        result.skip = TileSkipStats{true, 1 << s.tileShift, cursor.candidateTilePhases(), active};
    }
    result.nonFinite = s.nonFinite.read(s.ctx);
    s.hasRun = true;
    return result;
}

} // namespace voxc
