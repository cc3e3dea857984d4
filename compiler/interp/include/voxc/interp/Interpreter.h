#pragma once
// The CPU interpreter's stages, which voxc::interpret (voxc/stages/Pipeline.h) runs through the
// stage kinds' records on a DenseGrid, single-threaded, using only the shared definitions of the
// semantics (voxc/program/Semantics.h, voxc/builtins/Ops.h, voxc/builtins/Shapes.h). It is the oracle the Vulkan path is compared with bit for bit.
#include "voxc/grid/Grid.h"
#include "voxc/grid/NonFinite.h"
#include "voxc/interp/Slice.h"
#include "voxc/interp/Stats.h"
#include "voxc/interp/Trace.h"
#include "voxc/program/Program.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace voxc {

struct InterpOptions {
    // Called after each rule firing, in execution order (within a phase: x fastest, then y, z).
    std::function<void(const TraceEvent&)> onFire{};
    // When set, firing counts are added to it.
    FireStats* stats = nullptr;
    // When set, voxc::interpret resizes it to one entry per pipeline stage and counts there the
    // non-finite densities each stage replaced by 0 (voxc/grid/NonFinite.h).
    std::vector<NonFiniteCount>* nonFinite = nullptr;
    // When set, called before each stage, grammar iteration and field z slice with the fraction of the run
    // done (0 to 1, growing); it may throw to stop the run, which then leaves nothing behind
    // (libvoxc's progress callback, docs/embedding.md).
    std::function<void(double fraction)> progress{};
};

// The start state: startVoxel at every voxel of the world.
DenseGrid evaluateStart(const Program& program);

// Runs every iteration of one grammar in place. `grid` must have the world's size. A written
// value that is not finite (an ADD past the float range) is stored as 0 and, when `nonFinite`
// is set, counted there.
void runGrammar(const Program& program, uint32_t grammarIndex, DenseGrid& grid, const InterpOptions& options = {},
                NonFiniteCount* nonFinite = nullptr);

} // namespace voxc
