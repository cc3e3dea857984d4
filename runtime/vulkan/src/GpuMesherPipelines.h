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
    uint32_t pass[4];          // workgroups along x, items; zw unused
};
static_assert(sizeof(McPush) == 112, "must match mc_common.glsl; every device takes at least 128 bytes");

enum McPass : uint32_t { kMcTiles, kMcCount, kMcEmitVertices, kMcEmitMaterials, kMcPassCount };

// Descriptor set 0 of the passes (the buffers' meaning is in the shaders). A pass writes through
// storage buffers or storage texel buffers and reads through uniform texel buffers (lavapipe
// fetches texels as vector gathers, where it reads a storage buffer one lane at a time behind a
// branch per lane).
enum McBinding : uint32_t {
    kMcDensityTexels,  // the executor's densities, a float per voxel
    kMcMaterialTexels, // its material ids, a uint per voxel
    kMcTileStates,
    kMcVertices,
    kMcCellMaterials,   // per active cell, its triangles' material
    kMcQuadTexels, // the densities again, four to a texel
    kMcCountTileTexels, // per active tile, what mc_count.glsl needs of it
    kMcActiveCellTexels,
    kMcVertexEdgeTexels,
    kMcSegmentCases,
    kMcUnknownTileTexels, // the tiles mc_tiles.glsl reads
    kMcBindingCount
};
constexpr bool isMcTexelBinding(uint32_t binding) {
    return binding == kMcDensityTexels || binding == kMcMaterialTexels ||
           (binding >= kMcQuadTexels && binding <= kMcVertexEdgeTexels) || binding == kMcUnknownTileTexels;
}
// Written as texels (imageStore): lavapipe stores a texel's words in one pass over the lanes.
constexpr bool isMcStorageTexelBinding(uint32_t binding) { return binding == kMcCellMaterials || binding == kMcVertices; }

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
