#include "voxc/vulkan/GpuMesher.h"

#include "DeviceBuffer.h"
#include "CommandSlot.h"
#include "ExecutorVoxels.h"
#include "GpuMesherPipelines.h"
#include "voxc/core/Errors.h"
#include "voxc/mesh/MarchingCubes.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <vector>

namespace voxc {

using namespace vulkan_detail;

namespace {

constexpr uint32_t kCellsPerGroup = 64;    // local size of the emit pass
constexpr uint32_t kScanBlock = 1024;      // elements per count and scan workgroup (mc_count, mc_scan.glsl)
constexpr uint32_t kScanBlockShift = 10;
constexpr uint32_t kCaseWords = 10;        // per case: triangle count, 36 edge bytes
constexpr uint32_t kVertexWords = 7;       // position, normal, material
constexpr uint32_t kTriangleWords = 4;     // three indices, material
constexpr VkDeviceSize kTotalsBytes = 4 * sizeof(uint32_t); // a scan element: vertices, triangles, active cells
static_assert(kScanBlock == 1u << kScanBlockShift);

struct Access {
    VkPipelineStageFlags stage;
    VkAccessFlags access;
};
constexpr Access kCompute{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
constexpr Access kTransfer{VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT};
constexpr Access kComputeOrTransfer{kCompute.stage | kTransfer.stage, kCompute.access | kTransfer.access};
constexpr Access kHostRead{VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT};

// Between dispatches: the next one starts only after the last one's writes are visible to it.
void memoryBarrier(const VulkanApi& api, VkCommandBuffer cmd, Access before, Access after) {
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = before.access;
    b.dstAccessMask = after.access;
    api.vkCmdPipelineBarrier(cmd, before.stage, after.stage, 0, 1, &b, 0, nullptr, 0, nullptr);
}

// The case table as the shaders read it (kCaseWords per case).
std::vector<uint32_t> packedCaseTable() {
    std::vector<uint32_t> words(256 * kCaseWords, 0);
    const auto& table = marching_cubes::caseTable();
    for (size_t mask = 0; mask < 256; ++mask) {
        words[mask * kCaseWords] = table[mask].triangleCount;
        for (size_t i = 0; i < table[mask].edges.size(); ++i)
            words[mask * kCaseWords + 1 + i / 4] |= uint32_t(table[mask].edges[i]) << (8 * (i % 4));
    }
    return words;
}

std::string mib(uint64_t bytes) { return fmt::format("{:.1f} MiB", double(bytes) / (1 << 20)); }

} // namespace

struct GpuMarchingCubes::Impl {
    ExecutorVoxels source;
    VulkanContext::Impl& ctx;
    ChunkLayout layout;
    uint32_t cells = 0;                  // the cell domain, (gridSize + 1) per axis
    glm::ivec3 cellChunkFirst{0}, cellChunkCount{0};
    uint32_t chunkCount = 0;             // world chunks holding cells
    std::vector<uint32_t> levelSize;     // elements per scan level: the cells, ..., 1 (the totals)
    std::vector<uint32_t> levelOffset;   // of levels 1 and up in scanLevels ([0] unused: level 0 is cellPlaces)
    McPipelines pipelines;
    // `results` is host-visible: the totals and the chunk flags after the count, then the mesh.
    DeviceBuffer caseTable, chunkFlags, cellInfo, cellPlaces, scanLevels, activeCells, vertices, triangles, results;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;

    Impl(VulkanExecutor& executor) : source(executor.deviceVoxels()), ctx(*source.context), layout(executor.layout()) {}
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    ~Impl();

    void checkLimits() const;
    void createBuffers();
    // A buffer of at least `bytes` (storage and transfer source/destination), replaced when
    // smaller; true when replaced (a new buffer may reuse the old handle's value, so callers
    // cannot compare handles to know whether descriptors need an update).
    bool ensureBuffer(DeviceBuffer& buffer, VkDeviceSize bytes, MemoryUse use);
    McPush push(const MeshOptions& options) const;
    // Records `groups` workgroups of `pass`, split over x and y where x alone is not enough.
    void dispatch(McPass pass, McPush& push, uint32_t groups, uint32_t items);
    void begin();
    void submitAndWait();
};

GpuMarchingCubes::Impl::~Impl() {
    if (ctx.device) ctx.api.vkDeviceWaitIdle(ctx.device);
    if (fence) ctx.api.vkDestroyFence(ctx.device, fence, nullptr);
    if (commandPool) ctx.api.vkDestroyCommandPool(ctx.device, commandPool, nullptr);
    for (DeviceBuffer* b : {&results, &triangles, &vertices, &activeCells, &scanLevels, &cellPlaces, &cellInfo, &chunkFlags, &caseTable})
        destroyBuffer(ctx, *b);
    destroyMcPipelines(ctx, pipelines);
}

void GpuMarchingCubes::Impl::checkLimits() const {
    if (!ctx.shaderFloat64)
        throw UserError(fmt::format("the Vulkan device '{}' has no shaderFloat64, which marching cubes on the device needs "
                                    "(edge crossings are computed in double, as on the CPU); mesh on the host instead "
                                    "(voxc run --mesh-on host)",
                                    ctx.info.name));
    const uint64_t maxRange = ctx.properties.limits.maxStorageBufferRange;
    const uint64_t domain = uint64_t(layout.gridSize.x + 1) * uint64_t(layout.gridSize.y + 1) * uint64_t(layout.gridSize.z + 1);
    // Triangle places are 32-bit sums of up to 12 triangles per cell; the largest buffer holds a
    // uint per cell (cellInfo, cellPlaces).
    const uint64_t cellBytes = domain * sizeof(uint32_t);
    if (domain * marching_cubes::kMaxTrianglesPerCell > UINT32_MAX || cellBytes > maxRange)
        throw UserError(fmt::format("marching cubes on the device needs {} buffers for the {} cells of a {}x{}x{} grid, "
                                    "more than the Vulkan device '{}' can bind ({}); mesh on the host instead "
                                    "(voxc run --mesh-on host) or use a smaller grid",
                                    mib(cellBytes), domain, layout.gridSize.x, layout.gridSize.y, layout.gridSize.z,
                                    ctx.info.name, mib(maxRange)));
}

bool GpuMarchingCubes::Impl::ensureBuffer(DeviceBuffer& buffer, VkDeviceSize bytes, MemoryUse use) {
    if (buffer.buffer && buffer.size >= bytes) return false;
    destroyBuffer(ctx, buffer);
    const VkBufferUsageFlags usage =
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    buffer = createBuffer(ctx, bytes, usage, use);
    return true;
}

void GpuMarchingCubes::Impl::createBuffers() {
    const glm::ivec3 last = (layout.gridOrigin + layout.gridSize - 1) >> layout.chunkShift;
    cellChunkFirst = (layout.gridOrigin - 1) >> layout.chunkShift; // as voxc::cellChunks
    cellChunkCount = last - cellChunkFirst + 1;
    chunkCount = uint32_t(cellChunkCount.x) * uint32_t(cellChunkCount.y) * uint32_t(cellChunkCount.z);
    cells = uint32_t(layout.gridSize.x + 1) * uint32_t(layout.gridSize.y + 1) * uint32_t(layout.gridSize.z + 1);
    levelSize = {cells};
    do levelSize.push_back((levelSize.back() + kScanBlock - 1) / kScanBlock);
    while (levelSize.back() > 1);
    VOXC_ASSERT(levelSize.size() <= 4); // McPush::levelOffset
    levelOffset = {0};
    uint32_t offset = 0;
    for (size_t level = 1; level < levelSize.size(); ++level) {
        levelOffset.push_back(offset);
        offset += levelSize[level];
    }

    const std::vector<uint32_t> table = packedCaseTable();
    ensureBuffer(caseTable, table.size() * sizeof(uint32_t), MemoryUse::HostAccess);
    std::memcpy(caseTable.mapped, table.data(), table.size() * sizeof(uint32_t));
    flushForDevice(ctx, caseTable); // the queue submit makes it visible to the device
    ensureBuffer(chunkFlags, VkDeviceSize(chunkCount) * sizeof(uint32_t), MemoryUse::Device);
    ensureBuffer(cellInfo, VkDeviceSize(cells) * sizeof(uint32_t), MemoryUse::Device);
    ensureBuffer(cellPlaces, VkDeviceSize(cells) * sizeof(uint32_t), MemoryUse::Device);
    ensureBuffer(scanLevels, VkDeviceSize(offset) * kTotalsBytes, MemoryUse::Device);
    // Placeholders until a mesh has triangles: every binding of the set must name a buffer.
    ensureBuffer(activeCells, 16, MemoryUse::Device);
    ensureBuffer(vertices, 16, MemoryUse::Device);
    ensureBuffer(triangles, 16, MemoryUse::Device);
    ensureBuffer(results, kTotalsBytes + VkDeviceSize(chunkCount) * sizeof(uint32_t), MemoryUse::HostAccess);
}

McPush GpuMarchingCubes::Impl::push(const MeshOptions& options) const {
    McPush p{};
    for (int a = 0; a < 3; ++a) {
        p.gridOrigin[a] = layout.gridOrigin[a];
        p.gridSize[a] = layout.gridSize[a];
        p.chunkBase[a] = layout.chunkBase[a];
        p.cellChunkFirst[a] = cellChunkFirst[a];
        p.cellChunkCount[a] = cellChunkCount[a];
    }
    p.gridOrigin[3] = layout.chunkShift;
    p.gridSize[3] = source.hasMaterials ? 1 : 0;
    p.chunkBase[3] = layout.chunkCount.x;
    p.cellChunkFirst[3] = layout.chunkCount.y;
    p.cellChunkCount[3] = options.skipUniformChunks ? 1 : 0;
    const float margin = marching_cubes::crossingMargin(layout);
    p.surface[0] = options.iso;
    p.surface[1] = margin;
    p.surface[2] = 1.0f - margin;
    for (size_t l = 0; l < levelOffset.size(); ++l) p.levelOffset[l] = levelOffset[l];
    p.pass[1] = uint32_t(levelSize.size() - 1);
    return p;
}

void GpuMarchingCubes::Impl::dispatch(McPass pass, McPush& push, uint32_t groups, uint32_t items) {
    const uint32_t maxX = ctx.properties.limits.maxComputeWorkGroupCount[0];
    const uint32_t x = std::min(groups, maxX), y = (groups + x - 1) / x;
    VOXC_ASSERT(y <= ctx.properties.limits.maxComputeWorkGroupCount[1]); // groups < 2^32 / 64 by checkLimits
    push.pass[0] = x;
    push.pass[2] = items;
    ctx.api.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines.pipelines[pass]);
    ctx.api.vkCmdPushConstants(cmd, pipelines.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(McPush), &push);
    ctx.api.vkCmdDispatch(cmd, x, y, 1);
}

void GpuMarchingCubes::Impl::begin() {
    check(ctx.api.vkResetCommandBuffer(cmd, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(ctx.api.vkBeginCommandBuffer(cmd, &info), "vkBeginCommandBuffer");
    // The executor's writes (and this mesher's earlier reads of its own buffers) come first.
    memoryBarrier(ctx.api, cmd, kComputeOrTransfer, kComputeOrTransfer);
    ctx.api.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines.layout, 0, 1, &pipelines.set, 0, nullptr);
}

void GpuMarchingCubes::Impl::submitAndWait() {
    check(ctx.api.vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    VkSubmitInfo info{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    info.commandBufferCount = 1;
    info.pCommandBuffers = &cmd;
    check(ctx.api.vkQueueSubmit(ctx.queue, 1, &info, fence), "vkQueueSubmit");
    check(ctx.api.vkWaitForFences(ctx.device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    check(ctx.api.vkResetFences(ctx.device, 1, &fence), "vkResetFences");
}

GpuMarchingCubes::GpuMarchingCubes(VulkanExecutor& executor) : impl_(std::make_unique<Impl>(executor)) {
    Impl& s = *impl_;
    s.checkLimits();
    createMcPipelines(s.ctx, s.pipelines);
    s.createBuffers();
    bindMcBuffers(s.ctx, s.pipelines,
                  {s.source.voxels, s.source.materials, s.caseTable.buffer, s.chunkFlags.buffer, s.cellInfo.buffer,
                   s.scanLevels.buffer, s.vertices.buffer, s.triangles.buffer, s.cellPlaces.buffer, s.activeCells.buffer});
    const CommandSlot slot = createCommandSlot(s.ctx);
    s.commandPool = slot.pool;
    s.cmd = slot.commands;
    s.fence = slot.fence;
}

GpuMarchingCubes::~GpuMarchingCubes() = default;

Mesh GpuMarchingCubes::mesh(const MeshOptions& options, MeshStats* stats) {
    Impl& s = *impl_;
    if (!s.source.hasRun) throw InternalError("GPU marching cubes: the executor has not run, its voxel buffer holds no grid");
    const VulkanApi& api = s.ctx.api;
    McPush push = s.push(options);

    // Count and scan, then the totals (and which chunks were skipped) to the host.
    s.begin();
    if (options.skipUniformChunks) {
        s.dispatch(kMcChunks, push, s.chunkCount, s.chunkCount);
        memoryBarrier(api, s.cmd, kCompute, kCompute);
    }
    // The count scans its own 1024-cell blocks (level 0); the levels above follow.
    s.dispatch(kMcCount, push, (s.cells + kScanBlock - 1) / kScanBlock, s.cells);
    for (uint32_t level = 1; level + 1 < s.levelSize.size(); ++level) {
        memoryBarrier(api, s.cmd, kCompute, kCompute);
        push.pass[3] = level;
        s.dispatch(kMcScan, push, (s.levelSize[level] + kScanBlock - 1) / kScanBlock, s.levelSize[level]);
    }
    memoryBarrier(api, s.cmd, kCompute, kTransfer);
    const VkBufferCopy totals{VkDeviceSize(s.levelOffset.back()) * kTotalsBytes, 0, kTotalsBytes};
    api.vkCmdCopyBuffer(s.cmd, s.scanLevels.buffer, s.results.buffer, 1, &totals);
    if (options.skipUniformChunks) {
        const VkBufferCopy flags{0, kTotalsBytes, VkDeviceSize(s.chunkCount) * sizeof(uint32_t)};
        api.vkCmdCopyBuffer(s.cmd, s.chunkFlags.buffer, s.results.buffer, 1, &flags);
    }
    memoryBarrier(api, s.cmd, kTransfer, kHostRead);
    s.submitAndWait();
    invalidateForHost(s.ctx, s.results);
    uint32_t counts[3];
    std::memcpy(counts, s.results.mapped, sizeof counts);
    const uint32_t vertexCount = counts[0], triangleCount = counts[1], activeCount = counts[2];
    if (stats) {
        *stats = MeshStats{s.chunkCount, 0};
        if (options.skipUniformChunks) {
            std::vector<uint32_t> uniform(s.chunkCount);
            std::memcpy(uniform.data(), static_cast<const char*>(s.results.mapped) + kTotalsBytes, uniform.size() * sizeof(uint32_t));
            for (uint32_t flag : uniform) stats->skippedChunks += flag;
        }
    }
    Mesh mesh;
    if (triangleCount == 0) return mesh;

    // Emit into buffers of the counted size; words per element times the count stays below 2^32
    // because the byte size is at most maxStorageBufferRange.
    const uint64_t vertexBytes = uint64_t(vertexCount) * kVertexWords * sizeof(uint32_t);
    const uint64_t triangleBytes = uint64_t(triangleCount) * kTriangleWords * sizeof(uint32_t);
    const uint64_t maxRange = s.ctx.properties.limits.maxStorageBufferRange;
    if (std::max(vertexBytes, triangleBytes) > maxRange)
        throw UserError(fmt::format("the mesh has {} vertices and {} triangles, a {} and a {} buffer on the device, more than "
                                    "the Vulkan device '{}' can bind ({}); mesh on the host instead (voxc run --mesh-on host)",
                                    vertexCount, triangleCount, mib(vertexBytes), mib(triangleBytes), s.ctx.info.name, mib(maxRange)));
    const bool newVertices = s.ensureBuffer(s.vertices, vertexBytes, MemoryUse::Device);
    const bool newTriangles = s.ensureBuffer(s.triangles, triangleBytes, MemoryUse::Device);
    const bool newActive = s.ensureBuffer(s.activeCells, VkDeviceSize(activeCount) * sizeof(uint32_t), MemoryUse::Device);
    s.ensureBuffer(s.results, vertexBytes + triangleBytes, MemoryUse::HostAccess);
    if (newVertices || newTriangles || newActive) {
        std::array<VkBuffer, kMcBindingCount> buffers{};
        buffers[kMcVertices] = s.vertices.buffer;
        buffers[kMcTriangles] = s.triangles.buffer;
        buffers[kMcCellPlaces] = s.cellPlaces.buffer;
        buffers[kMcActiveCells] = s.activeCells.buffer;
        bindMcBuffers(s.ctx, s.pipelines, buffers, kMcVertices, kMcBindingCount);
    }
    // The active cells in cell order, then the emit over them alone.
    s.begin();
    s.dispatch(kMcCompact, push, (s.cells + kScanBlock - 1) / kScanBlock, s.cells); // 16 cells per invocation
    memoryBarrier(api, s.cmd, kCompute, kCompute);
    s.dispatch(kMcEmit, push, (activeCount + kCellsPerGroup - 1) / kCellsPerGroup, activeCount);
    memoryBarrier(api, s.cmd, kCompute, kTransfer);
    const VkBufferCopy vertexCopy{0, 0, vertexBytes};
    api.vkCmdCopyBuffer(s.cmd, s.vertices.buffer, s.results.buffer, 1, &vertexCopy);
    const VkBufferCopy triangleCopy{0, vertexBytes, triangleBytes};
    api.vkCmdCopyBuffer(s.cmd, s.triangles.buffer, s.results.buffer, 1, &triangleCopy);
    memoryBarrier(api, s.cmd, kTransfer, kHostRead);
    s.submitAndWait();
    invalidateForHost(s.ctx, s.results);

    const auto* words = static_cast<const uint32_t*>(s.results.mapped);
    auto floatAt = [&](size_t i) {
        float f;
        std::memcpy(&f, &words[i], sizeof f);
        return f;
    };
    mesh.positions.resize(vertexCount);
    mesh.normals.resize(vertexCount);
    mesh.vertexMaterials.resize(vertexCount);
    for (size_t v = 0; v < vertexCount; ++v) {
        const size_t w = v * kVertexWords;
        mesh.positions[v] = {floatAt(w), floatAt(w + 1), floatAt(w + 2)};
        mesh.normals[v] = {floatAt(w + 3), floatAt(w + 4), floatAt(w + 5)};
        mesh.vertexMaterials[v] = uint8_t(words[w + 6]);
    }
    const uint32_t* triangleWords = words + vertexBytes / sizeof(uint32_t);
    mesh.triangles.resize(size_t(triangleCount) * 3);
    mesh.triangleMaterials.resize(triangleCount);
    for (size_t t = 0; t < triangleCount; ++t) {
        for (size_t k = 0; k < 3; ++k) {
            const uint32_t index = triangleWords[t * kTriangleWords + k];
            if (index >= vertexCount) throw InternalError("GPU marching cubes: a triangle names a vertex past the counted ones");
            mesh.triangles[t * 3 + k] = index;
        }
        mesh.triangleMaterials[t] = uint8_t(triangleWords[t * kTriangleWords + 3]);
    }
    // The host mesher's last step, on the host: the same function of the same mesh.
    orientNormalsToFaces(mesh);
    return mesh;
}

} // namespace voxc
