#include "voxc/vulkan/DispatchPlan.h"

#include "voxc/core/Errors.h"
#include "voxc/grid/Grid.h"

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <bit>
#include <cstring>

namespace voxc {

namespace {

constexpr uint32_t kSpirvMagic = 0x07230203;

void packageError(const std::string& what) { throw InternalError("invalid kernel package: " + what); }

// The tiles of 2^tileShift voxels along one axis that hold an anchor origin + start + i * step,
// i < count (world coordinates; the anchors ascend, so equal tiles are neighbours).
uint64_t tilesHoldingAnchors(int32_t origin, int32_t start, int32_t step, int32_t count, int32_t tileShift) {
    uint64_t tiles = 0;
    for (int32_t i = 0, last = 0; i < count; ++i) {
        const int32_t tile = (origin + start + i * step) >> tileShift;
        tiles += (i == 0 || tile != last) ? 1 : 0;
        last = tile;
    }
    return tiles;
}

void setXyz(int32_t (&field)[4], glm::ivec3 v, int32_t w) {
    field[0] = v.x;
    field[1] = v.y;
    field[2] = v.z;
    field[3] = w;
}

} // namespace

void validatePackage(const KernelPackage& package) {
    const World& world = package.world;
    if (world.chunkSize <= 0 || (world.chunkSize & (world.chunkSize - 1)) != 0)
        packageError(fmt::format("chunk size {} is not a power of two", world.chunkSize));
    if (world.size.x <= 0 || world.size.y <= 0 || world.size.z <= 0) packageError("empty grid");
    for (const Kernel& kernel : package.kernels) {
        if (kernel.spirv.size() < 5 || kernel.spirv[0] != kSpirvMagic)
            packageError(fmt::format("kernel '{}' has no SPIR-V", kernel.name));
        if (kernel.localSize[0] == 0 || kernel.localSize[1] == 0 || kernel.localSize[2] == 0)
            packageError(fmt::format("kernel '{}' has a zero local size", kernel.name));
        if (kernel.anchorsPerInvocation[0] == 0 || kernel.anchorsPerInvocation[1] == 0 ||
            kernel.anchorsPerInvocation[2] == 0)
            packageError(fmt::format("kernel '{}' has zero anchors per invocation", kernel.name));
    }
    const auto checkKernel = [&](uint32_t index) {
        if (index >= package.kernels.size())
            packageError(fmt::format("kernel index {} out of range ({} kernels)", index, package.kernels.size()));
    };
    for (const StagePlan& stage : package.stages) {
        if (stage.material && !package.usesMaterials)
            packageError(fmt::format("stage '{}' writes a material but the package has no material buffer", stage.label));
        if (stage.prepassKernel != kNoKernel) {
            checkKernel(stage.prepassKernel);
            if (stage.gridKernel == kNoKernel)
                packageError(fmt::format("stage '{}' has a prepass but no grid pass", stage.label));
        }
        if (stage.gridKernel != kNoKernel) {
            checkKernel(stage.gridKernel);
            // Boxes inside the grid whose volumes sum to the grid's (the codegen tiles it with chunks).
            uint64_t volume = 0;
            for (const FieldBox& box : stage.gridBoxes) {
                if (glm::any(glm::lessThan(box.min, glm::ivec3(0))) ||
                    glm::any(glm::greaterThan(box.max, package.world.size)) ||
                    glm::any(glm::greaterThanEqual(box.min, box.max)))
                    packageError(fmt::format("stage '{}': a box lies outside the grid or is empty", stage.label));
                const glm::i64vec3 extent = glm::i64vec3(box.max - box.min);
                volume += uint64_t(extent.x * extent.y * extent.z);
            }
            const glm::i64vec3 grid = glm::i64vec3(package.world.size);
            if (!stage.gridBoxes.empty() && volume != uint64_t(grid.x * grid.y * grid.z))
                packageError(fmt::format("stage '{}': its boxes do not cover the grid", stage.label));
        }
        if (!stage.grammar) continue;
        for (const SweepPlan& sweep : stage.grammar->sweeps) {
            checkKernel(sweep.kernel);
            if (sweep.stampKernel != kNoKernel) checkKernel(sweep.stampKernel);
            if (sweep.phaseStep.size() != sweep.phaseStart.size() || sweep.phaseCount3.size() != sweep.phaseStart.size())
                packageError(fmt::format("grammar '{}': phase arrays differ in length", stage.grammar->name));
        }
    }
}

uint64_t tileCount(const KernelPackage& package, int32_t tileShift) {
    const World& world = package.world;
    const ChunkLayout layout = ChunkLayout::make(world.origin, world.size, world.chunkSize);
    const uint64_t perAxis = uint64_t(world.chunkSize) >> tileShift;
    return layout.chunkTotal() * perAxis * perAxis * perAxis;
}

int32_t skipTileShift(const KernelPackage& package, std::array<uint32_t, 3> maxGroups) {
    if (package.tileRangesKernel == kNoKernel) return -1;
    const World& world = package.world;
    const ChunkLayout layout = ChunkLayout::make(world.origin, world.size, world.chunkSize);
    // Tiles of 8^3 voxels: a finer grid costs more in the active-tiles kernels than it saves, and
    // the active-tiles kernels rely on tiles of at least 8 (ActiveTilesKernel.cpp, kMinTileSize).
    for (int32_t shift = 3; shift <= layout.chunkShift; ++shift) {
        const uint64_t tiles = tileCount(package, shift);
        // The tile kernels run an invocation per tile in workgroups of 8 (tile_ranges) or 64
        // (active tiles); the sweep's workgroups of 64 invocations hold one anchor each (a tile
        // holds at most 8^shift anchors).
        const uint64_t groupsPerTile = ((uint64_t(1) << (3 * shift)) + 63) / 64;
        if (tiles <= maxGroups[1] && (tiles + 7) / 8 <= maxGroups[0] && groupsPerTile <= maxGroups[0])
            return shift;
    }
    return -1;
}

DispatchCursor::DispatchCursor(const KernelPackage& package, std::array<uint32_t, 3> maxGroups, int32_t tileShift)
    : package_(package), maxGroups_(maxGroups), tileShift_(tileShift) {
    for (uint32_t& g : maxGroups_) g = std::max(g, 1u);
    const World& world = package.world;
    const ChunkLayout layout = ChunkLayout::make(world.origin, world.size, world.chunkSize);
    int32_t seedBits;
    std::memcpy(&seedBits, &world.seed, sizeof seedBits);
    setXyz(base_.gridOrigin, world.origin, world.chunkSize);
    setXyz(base_.gridSize, world.size, seedBits);
    setXyz(base_.chunkBase, layout.chunkBase, 0);
    setXyz(base_.chunkCount, layout.chunkCount, 0);
    if (skipping()) base_.anchorStep[3] = tileShift;
}

bool DispatchCursor::next(Dispatch& out) {
    while (position_ == step_.size()) {
        if (!expandNextStep()) return false;
    }
    out = step_[position_++];
    return true;
}

// A stage is one step for its grid pass, then one step per iteration of its sweeps.
bool DispatchCursor::expandNextStep() {
    step_.clear();
    position_ = 0;
    while (stage_ < package_.stages.size()) {
        const StagePlan& stage = package_.stages[stage_];
        if (stageStep_ == 0 && stage.gridKernel != kNoKernel) {
            ++stageStep_;
            appendGridPass(stage);
            for (Dispatch& d : step_) d.stage = uint32_t(stage_);
            return true;
        }
        const uint32_t iterations = stage.grammar ? stage.grammar->iterations : 0;
        if (iteration_ >= iterations) {
            ++stage_;
            iteration_ = 0;
            stageStep_ = 0;
            continue;
        }
        ++stageStep_;
        const int32_t iteration = int32_t(iteration_++);
        for (size_t s = 0; s < stage.grammar->sweeps.size(); ++s) {
            const SweepPlan& sweep = stage.grammar->sweeps[s];
            if (sweep.stampKernel != kNoKernel) {
                appendStampingSweep(sweep, iteration, int32_t(s));
                continue;
            }
            if (skipping()) {
                appendSkippingSweep(sweep, iteration, int32_t(s));
                continue;
            }
            for (size_t p = 0; p < sweep.phaseStart.size(); ++p)
                appendPhase(sweep.kernel, iteration, int32_t(s), sweep.phaseStart[p], sweep.phaseStep[p],
                            sweep.phaseCount3[p]);
        }
        for (Dispatch& d : step_) d.stage = uint32_t(stage_);
        return true;
    }
    return false;
}

// One dispatch over the grid, or per box (a constant box's value travels in the w lanes); then
// every tile range is stale unless the stage writes materials only, which ranges do not track.
void DispatchCursor::appendGridPass(const StagePlan& stage) {
    if (stage.prepassKernel != kNoKernel)
        appendPhase(stage.prepassKernel, 0, 0, glm::ivec3(0), glm::ivec3(1), package_.world.size);
    if (stage.gridBoxes.empty()) {
        appendPhase(stage.gridKernel, 0, 0, glm::ivec3(0), glm::ivec3(1), package_.world.size);
    } else {
        for (const FieldBox& box : stage.gridBoxes) {
            if (box.unchanged) continue;
            const size_t first = step_.size();
            appendPhase(stage.gridKernel, 0, 0, box.min, glm::ivec3(1), box.max - box.min);
            for (size_t i = first; i < step_.size(); ++i) {
                step_[i].push.anchorStart[3] = box.constant ? std::bit_cast<int32_t>(box.value) : 0;
                step_[i].push.anchorCount[3] = box.constant ? 1 : 0;
            }
        }
    }
    if (skipping() && stage.writesDensities) {
        Dispatch invalidate;
        invalidate.kind = DispatchKind::InvalidateRanges;
        step_.push_back(invalidate);
    }
}

void DispatchCursor::appendPhase(uint32_t kernel, int32_t iteration, int32_t sweep, glm::ivec3 start,
                                 glm::ivec3 step, glm::ivec3 count) {
    if (count.x <= 0 || count.y <= 0 || count.z <= 0) return; // nothing to do; a dispatch of zero is not allowed
    const Kernel& k = package_.kernels[kernel];
    // Anchors one workgroup covers along each axis.
    uint64_t perGroup[3];
    for (int a = 0; a < 3; ++a) perGroup[a] = uint64_t(k.localSize[a]) * k.anchorsPerInvocation[a];
    // Anchors per piece along each axis: as many as maxGroups workgroups cover.
    glm::ivec3 piece;
    for (int a = 0; a < 3; ++a)
        piece[a] = int32_t(std::min<uint64_t>(uint64_t(maxGroups_[a]) * perGroup[a], uint64_t(count[a])));
    for (int32_t oz = 0; oz < count.z; oz += piece.z)
        for (int32_t oy = 0; oy < count.y; oy += piece.y)
            for (int32_t ox = 0; ox < count.x; ox += piece.x) {
                const glm::ivec3 offset(ox, oy, oz);
                const glm::ivec3 n = glm::min(piece, count - offset);
                Dispatch d;
                d.kernel = kernel;
                d.push = base_;
                d.push.chunkBase[3] = iteration;
                d.push.chunkCount[3] = sweep;
                setXyz(d.push.anchorStart, start + offset * step, 0);
                setXyz(d.push.anchorStep, step, 0);
                setXyz(d.push.anchorCount, n, 0);
                for (int a = 0; a < 3; ++a) d.groups[a] = uint32_t((uint64_t(n[a]) + perGroup[a] - 1) / perGroup[a]);
                step_.push_back(d);
            }
}

// Per phase: the sweep kernel over every anchor, then its stamp pass over the phase's windows
// grown by the reach, clipped to the grid (anchorStep.xyz carries the phase's first anchor).
// The stamps write outside the tiles the ranges track, so a skipping run invalidates them after.
void DispatchCursor::appendStampingSweep(const SweepPlan& sweep, int32_t iteration, int32_t sweepIndex) {
    for (size_t p = 0; p < sweep.phaseStart.size(); ++p) {
        const glm::ivec3 start = sweep.phaseStart[p], step = sweep.phaseStep[p], count = sweep.phaseCount3[p];
        if (count.x <= 0 || count.y <= 0 || count.z <= 0) continue;
        appendPhase(sweep.kernel, iteration, sweepIndex, start, step, count);
        const glm::ivec3 lo = glm::max(start - sweep.stampReach, glm::ivec3(0));
        const glm::ivec3 hi = glm::min(start + (count - 1) * step + sweep.window + sweep.stampReach, package_.world.size);
        const size_t first = step_.size();
        appendPhase(sweep.stampKernel, iteration, sweepIndex, lo, glm::ivec3(1), hi - lo);
        for (size_t i = first; i < step_.size(); ++i) setXyz(step_[i].push.anchorStep, start, 0);
    }
    if (skipping()) {
        Dispatch invalidate;
        invalidate.kind = DispatchKind::InvalidateRanges;
        step_.push_back(invalidate);
    }
}

void DispatchCursor::appendSkippingSweep(const SweepPlan& sweep, int32_t iteration, int32_t sweepIndex) {
    if (sweep.activeTilesKernel == kNoKernel) return; // no live rule: nothing can change
    // Both tile kernels run one invocation per tile id along x.
    const uint64_t tiles = tileCount(package_, tileShift_);
    const auto groupsFor = [&](uint32_t kernel) {
        const Kernel& k = package_.kernels[kernel];
        const uint64_t perGroup = uint64_t(k.localSize[0]) * k.localSize[1] * k.localSize[2];
        return uint32_t((tiles + perGroup - 1) / perGroup);
    };
    Dispatch ranges;
    ranges.kernel = package_.tileRangesKernel;
    ranges.push = base_;
    ranges.groups[0] = groupsFor(ranges.kernel);
    step_.push_back(ranges);

    for (size_t p = 0; p < sweep.phaseStart.size(); ++p) {
        const glm::ivec3 count = sweep.phaseCount3[p];
        if (count.x <= 0 || count.y <= 0 || count.z <= 0) continue;
        uint64_t candidates = 1;
        for (int a = 0; a < 3; ++a)
            candidates *= tilesHoldingAnchors(package_.world.origin[a], sweep.phaseStart[p][a], sweep.phaseStep[p][a],
                                              count[a], tileShift_);
        candidateTilePhases_ += candidates;
        Dispatch d;
        d.push = base_;
        d.push.chunkBase[3] = iteration;
        d.push.chunkCount[3] = sweepIndex;
        setXyz(d.push.anchorStart, sweep.phaseStart[p], int32_t(record_));
        setXyz(d.push.anchorStep, sweep.phaseStep[p], tileShift_);
        setXyz(d.push.anchorCount, count, 1);
        d.record = record_;
        d.kernel = sweep.activeTilesKernel;
        d.groups[0] = groupsFor(d.kernel);
        step_.push_back(d);
        d.kind = DispatchKind::Indirect;
        d.kernel = sweep.kernel;
        d.groups[0] = d.groups[1] = d.groups[2] = 0; // the active-tiles kernel writes them
        step_.push_back(d);
        record_ ^= 1u;
    }
}

uint64_t countDispatches(const KernelPackage& package, std::array<uint32_t, 3> maxGroups) {
    DispatchCursor cursor(package, maxGroups);
    Dispatch d;
    uint64_t n = 0;
    while (cursor.next(d)) ++n;
    return n;
}

} // namespace voxc
