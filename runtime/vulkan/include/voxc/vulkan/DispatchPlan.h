#pragma once
// Expands a KernelPackage's stage plans into the exact sequence of compute dispatches the
// executor records, one at a time, so a plan with many iterations never sits in memory
// as a list. Pure (no Vulkan), so the order and push constants are testable without a device.
#include "voxc/codegen/KernelPackage.h"

#include <array>
#include <cstdint>
#include <vector>

namespace voxc {

enum class DispatchKind : uint8_t {
    Direct,           // vkCmdDispatch of `groups`
    Indirect,         // vkCmdDispatchIndirect of active-dispatch record `record` (kBindingActiveDispatch)
    InvalidateRanges, // no kernel: every tile's density range is stale (the start kernel rewrote the grid)
};

struct Dispatch {
    DispatchKind kind = DispatchKind::Direct;
    uint32_t kernel = 0;
    PushBlock push{};
    uint32_t groups[3] = {1, 1, 1}; // workgroups: ceil(anchorCount / (localSize * anchorsPerInvocation)) per axis
    uint32_t record = 0;            // Indirect: which of the two records the active-tiles kernel wrote
    uint32_t stage = 0;             // index into KernelPackage::stages of the stage it belongs to
};

// Checks what the executor relies on (kernel indices, phase arrays of equal length, SPIR-V
// present, power-of-two chunk size); throws InternalError naming the problem, since a bad
// package is a compiler bug.
void validatePackage(const KernelPackage& package);

// How tile skipping would run the package: log2 of the tile size (the smallest of 8 voxels and
// the chunk size, doubled while the tile-sized dispatches do not fit in `maxGroups`; an
// indirect dispatch cannot be split), or -1 when the package lacks the kernels or no tile fits.
int32_t skipTileShift(const KernelPackage& package, std::array<uint32_t, 3> maxGroups);

// The number of tiles of 2^tileShift voxels per axis the package's chunk table holds.
uint64_t tileCount(const KernelPackage& package, int32_t tileShift);

class DispatchCursor {
public:
    // `maxGroups`: the device's maxComputeWorkGroupCount; a phase needing more workgroups
    // along an axis is split into several dispatches over disjoint anchor ranges.
    // `tileShift` >= 0 (skipTileShift's answer): sweeps run only over their phases' active tiles.
    DispatchCursor(const KernelPackage& package, std::array<uint32_t, 3> maxGroups, int32_t tileShift = -1);

    // Start (and field) stage: one dispatch of startKernel (fieldKernel) over the whole grid
    // (then, when skipping tiles, InvalidateRanges); a field stage with fieldBoxes dispatches per
    // box instead (skipping `unchanged` ones), a constant box with anchorCount.w = 1 and the
    // value's bits in anchorStart.w. A stage with a prepass kernel (speleothems) dispatches it once
    // over the whole grid first. Grammar stage: for each iteration, each sweep (index in
    // GrammarPlan::sweeps), each phase with anchors, in order. When skipping tiles a sweep
    // without live rules is left out, and a sweep with some is the tile_ranges kernel (one
    // invocation per tile), then per phase its active-tiles kernel (one invocation per tile,
    // records alternating 0, 1, 0, ... over the run) and the sweep kernel indirectly; both
    // carry the phase's push block with anchorStart.w = record and anchorCount.w = 1. Every
    // push block then has anchorStep.w = tileShift. A sweep with a stamp kernel runs each phase
    // directly, then its stamp pass, skipping or not (then InvalidateRanges when skipping).
    // Returns false when the plan is exhausted.
    bool next(Dispatch& out);

    // When skipping tiles: the (tile, phase) pairs of the sweeps expanded so far whose tile holds
    // anchors of the phase, which the active-tiles kernels classify (TileSkipStats::tilePhases).
    uint64_t candidateTilePhases() const { return candidateTilePhases_; }

private:
    // Queues the dispatches of the next stage step (a stage's grid pass, or one iteration of its sweeps).
    bool expandNextStep();
    void appendGridPass(const StagePlan& stage);
    void appendPhase(uint32_t kernel, int32_t iteration, int32_t sweep, glm::ivec3 start, glm::ivec3 step,
                     glm::ivec3 count);
    void appendSkippingSweep(const SweepPlan& sweep, int32_t iteration, int32_t sweepIndex);
    void appendStampingSweep(const SweepPlan& sweep, int32_t iteration, int32_t sweepIndex);
    bool skipping() const { return tileShift_ >= 0; }

    const KernelPackage& package_;
    std::array<uint32_t, 3> maxGroups_;
    int32_t tileShift_ = -1;
    uint32_t record_ = 0;      // the next phase's active-dispatch record
    PushBlock base_{};         // the fields every dispatch shares
    size_t stage_ = 0;         // next stage to expand
    uint32_t iteration_ = 0;   // next iteration of the current stage's sweeps
    uint32_t stageStep_ = 0;   // steps of the current stage expanded so far
    std::vector<Dispatch> step_;
    size_t position_ = 0;
    uint64_t candidateTilePhases_ = 0;
};

// Number of dispatches a package expands to (walks the whole plan).
uint64_t countDispatches(const KernelPackage& package, std::array<uint32_t, 3> maxGroups);

} // namespace voxc
