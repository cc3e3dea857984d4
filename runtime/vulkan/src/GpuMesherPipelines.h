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
    int32_t gridSize[4];       // w unused
    int32_t chunkBase[4];      // w: voxel-buffer slots along x
    int32_t tileFirst[4];      // first 8^3 tile of cells; w: voxel-buffer slots along y
    int32_t tileCount[4];      // tiles of cells per axis; w unused
    float surface[4];          // iso, margin, 1 - margin
    uint32_t levelOffset[4];   // scan levels 0..3 in the scan buffer, in elements
    uint32_t pass[4];          // workgroups along x, scanned levels, items, scan level
};
static_assert(sizeof(McPush) == 128, "must match mc_common.glsl; 128 bytes is every device's minimum");

enum McPass : uint32_t { kMcTiles, kMcCount, kMcScan, kMcCompact, kMcEmitVertices, kMcEmitTriangles, kMcPassCount };

// Descriptor set 0 of the passes (the buffers' meaning is in the shaders). A pass writes through
// storage buffers and reads through uniform texel buffers (lavapipe fetches texels as vector
// gathers, where it reads a storage buffer one lane at a time behind a branch per lane), so a
// buffer one pass writes and a later one reads is bound twice.
enum McBinding : uint32_t {
    kMcDensityTexels,  // the executor's densities, a float per voxel
    kMcMaterialTexels, // its material ids, a uint per voxel
    kMcCaseTexels,
    kMcTileStates,
    kMcCellInfo,
    kMcScanLevels,
    kMcVertices,
    kMcTriangles,
    kMcActiveCells,
    kMcQuadTexels, // the densities again, four to a texel
    kMcTileRankTexels,
    kMcActiveTileTexels,
    kMcSegmentTexels,
    kMcVertexEdges,
    kMcCellInfoTexels,
    kMcScanTexels,
    kMcActiveCellTexels,
    kMcVertexEdgeTexels,
    kMcSegmentCases,
    kMcSegmentCaseTexels,
    kMcUnknownTileTexels, // the tiles mc_tiles.glsl reads
    kMcBindingCount
};
constexpr bool isMcTexelBinding(uint32_t binding) {
    return binding == kMcDensityTexels || binding == kMcMaterialTexels || binding == kMcCaseTexels || binding == kMcQuadTexels ||
           (binding >= kMcTileRankTexels && binding <= kMcSegmentTexels) ||
           (binding >= kMcCellInfoTexels && binding <= kMcVertexEdgeTexels) || binding == kMcSegmentCaseTexels ||
           binding == kMcUnknownTileTexels;
}
// Written as texels (imageStore): lavapipe stores a texel's words in one pass over the lanes.
constexpr bool isMcStorageTexelBinding(uint32_t binding) {
    return binding == kMcTriangles || binding == kMcActiveCells || binding == kMcVertices || binding == kMcCellInfo ||
           binding == kMcVertexEdges;
}
constexpr VkFormat mcStorageTexelFormat(uint32_t binding) {
    return binding == kMcCellInfo || binding == kMcVertexEdges ? VK_FORMAT_R32_UINT : VK_FORMAT_R32G32B32A32_UINT;
}

struct McPipelines : StorageSet {
    std::array<VkPipeline, kMcPassCount> pipelines{};
};

// Compiles the passes (glslang) and builds their pipelines; fills `out` step by step, so
// destroyMcPipelines cleans up after a failure part way.
// `hasMaterials`: the executor's material buffer has a uint per voxel (else every id reads 0).
void createMcPipelines(VulkanContext::Impl& ctx, bool hasMaterials, McPipelines& out);
// Points every storage binding b at buffers[b] and every texel binding b at views[b].
void bindMcSet(VulkanContext::Impl& ctx, const McPipelines& pipelines, const std::array<VkBuffer, kMcBindingCount>& buffers,
               const std::array<VkBufferView, kMcBindingCount>& views);
void destroyMcPipelines(VulkanContext::Impl& ctx, McPipelines& pipelines);

} // namespace voxc::vulkan_detail
