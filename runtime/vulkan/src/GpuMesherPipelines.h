#pragma once
// The compute pipelines of the GPU marching-cubes passes (compiler/shaders/mc_*.glsl) and the
// one descriptor set they share.
#include "StorageSet.h"

#include <array>
#include <cstdint>

namespace voxc::vulkan_detail {

// The push block of compiler/shaders/mc_common.glsl, field for field (std430).
struct McPush {
    int32_t gridOrigin[4];     // w: log2 chunk size
    int32_t gridSize[4];       // w: 1 when the material buffer has a uint per voxel
    int32_t chunkBase[4];      // w: voxel-buffer slots along x
    int32_t tileFirst[4];      // first 8^3 tile of cells; w: voxel-buffer slots along y
    int32_t tileCount[4];      // tiles of cells per axis; w unused
    float surface[4];          // iso, margin, 1 - margin
    uint32_t levelOffset[4];   // scan levels 0..3 in the scan buffer, in elements
    uint32_t pass[4];          // workgroups along x, scanned levels, items, scan level
};
static_assert(sizeof(McPush) == 128, "must match mc_common.glsl; 128 bytes is every device's minimum");

enum McPass : uint32_t { kMcTiles, kMcCount, kMcScan, kMcCompact, kMcEmitVertices, kMcEmitTriangles, kMcPassCount };

// Descriptor set 0 of the passes (the buffers' meaning is in the shaders).
enum McBinding : uint32_t {
    kMcVoxels,
    kMcMaterials,
    kMcCaseTable,
    kMcTileStates,
    kMcCellInfo,
    kMcScanLevels,
    kMcVertices,
    kMcTriangles,
    kMcActiveCells,
    kMcVoxelQuads, // the voxel buffer again, as vec4
    kMcTileRanks,
    kMcActiveTiles,
    kMcSegments,
    kMcVertexEdges,
    kMcBindingCount
};

struct McPipelines : StorageSet {
    std::array<VkPipeline, kMcPassCount> pipelines{};
};

// Compiles the passes (glslang) and builds their pipelines; fills `out` step by step, so
// destroyMcPipelines cleans up after a failure part way.
void createMcPipelines(VulkanContext::Impl& ctx, McPipelines& out);
// Points binding b at buffers[b] for every b in [first, last).
void bindMcBuffers(VulkanContext::Impl& ctx, const McPipelines& pipelines, const std::array<VkBuffer, kMcBindingCount>& buffers,
                   uint32_t first = 0, uint32_t last = kMcBindingCount);
void destroyMcPipelines(VulkanContext::Impl& ctx, McPipelines& pipelines);

} // namespace voxc::vulkan_detail
