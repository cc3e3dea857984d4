#pragma once
// Runs a KernelPackage on a VulkanContext: one compute pipeline per kernel, a chunk-major
// voxel buffer laid out as ChunkLayout::make(world.origin, world.size, world.chunkSize) (and a
// material buffer at the same addresses when KernelPackage::usesMaterials), and
// every dispatch of the plan in order (DispatchCursor), each phase behind a barrier on the
// previous one. The pipelines and buffers live as long as the executor, so run() can be
// repeated (benchmarks) without recompiling anything.
#include "voxc/codegen/KernelPackage.h"
#include "voxc/grid/Grid.h"
#include "voxc/grid/NonFinite.h"
#include "voxc/vulkan/Context.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace voxc {

namespace vulkan_detail {
struct ExecutorVoxels;
}

struct ExecutorOptions {
    // Dispatches per command buffer. Batches are recorded while the previous one executes,
    // so a plan with many iterations never holds all of its commands at once.
    uint32_t dispatchesPerBatch = 4096;
    // When above 0, batches are sized so that one finishes about every batchMilliseconds (at
    // most dispatchesPerBatch dispatches, at least one): `progress`, called between batches, then
    // runs that often, and a run it stops ends that soon (two batches are in flight). The size
    // follows the time between batches finishing, at most halving or doubling from one to the next.
    double batchMilliseconds = 0;
    // Copy through staging buffers even where device memory is host-visible (integrated GPUs,
    // lavapipe), i.e. what a discrete GPU does; lets tests cover that path on lavapipe.
    bool alwaysStage = false;
    // Per-axis workgroup-count limit; 0 means the device's maxComputeWorkGroupCount. Tests
    // lower it to exercise split dispatches.
    std::array<uint32_t, 3> maxWorkGroups{0, 0, 0};
    // Run each sweep phase only over the tiles (8^3 voxels) where some rule may match (see
    // DispatchCursor); ignored where the package or the device limits do not allow it (skipTileShift).
    bool skipInactiveTiles = true;
    // Copy the voxels into RunResult::grid after each run. false leaves them in the device's
    // buffers only (deviceVoxels(), for the GPU mesher) and the grid empty: a caller that meshes
    // on the device and writes no voxels skips copying (and allocating) the whole grid.
    bool readBack = true;
    // When set, called before each batch is recorded with the fraction of the package's stages
    // reached (0 to 1); it may throw to stop the run: the batches in flight are waited for and the
    // exception leaves run() (libvoxc's progress callback, docs/embedding.md). batchMilliseconds
    // says how often.
    std::function<void(double fraction)> progress{};
};

// How much tile skipping saved in one run: counts of (tile, phase) pairs, summed over every
// phase of every sweep with live rules (32-bit counters on the device).
struct TileSkipStats {
    bool enabled = false;          // the run skipped tiles
    int32_t tileSize = 0;          // voxels per axis of a tile
    uint64_t tilePhases = 0;       // tiles holding anchors of a phase
    uint64_t activeTilePhases = 0; // of those, the ones dispatched (some rule may match there)
};

struct RunTimings {
    double setupMs = 0;    // executor construction: pipelines, buffers, chunk-table upload (same every run)
    double recordMs = 0;   // command recording in this run (overlaps execution after the first batch)
    double executeMs = 0;  // first submit -> last fence signalled
    double readbackMs = 0; // device results -> ChunkedGrid, with its tile ranges (ChunkedGrid::loadDensities)
};

struct RunResult {
    ChunkedGrid grid;
    RunTimings timings;
    uint64_t dispatches = 0; // vkCmdDispatch and vkCmdDispatchIndirect calls recorded
    TileSkipStats skip;
    // Per KernelPackage::stages entry: the non-finite densities the stage replaced by 0
    // (voxc/grid/NonFinite.h), read back from the kernels' counters.
    std::vector<NonFiniteCount> nonFinite;
};

class VulkanExecutor {
public:
    // Validates the package (InternalError when malformed), checks the voxel buffer against the
    // device limits (UserError when the grid is too large), builds pipelines and buffers and
    // uploads the chunk table. `context` must outlive the executor; the package is copied.
    VulkanExecutor(VulkanContext& context, const KernelPackage& package, const ExecutorOptions& options = {});
    ~VulkanExecutor();
    VulkanExecutor(const VulkanExecutor&) = delete;
    VulkanExecutor& operator=(const VulkanExecutor&) = delete;

    // Clears the voxel and material buffers to 0 (the voxels not where the first stage writes every
    // one of them and the chunks hold no padding), runs every dispatch of the plan, returns the
    // grid (densities, and materials when the package uses them; otherwise every voxel `none`;
    // an empty grid when ExecutorOptions::readBack is false).
    RunResult run();

    const ChunkLayout& layout() const;
    double setupMs() const;
    // The device's voxel and material buffers as the last run() left them (src/ExecutorVoxels.h;
    // opaque here so that this header stays free of Vulkan types), for the GPU mesher.
    vulkan_detail::ExecutorVoxels deviceVoxels() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace voxc
