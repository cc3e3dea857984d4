// The pipeline's work estimate against Limits::maxWork: every stage adds what running it costs,
// in the same units for both backends (one window cell tested, one shape or DAG node evaluated
// at one voxel), and the stage at which the sum passes the budget is reported.
#include "Sections.h"
#include "Values.h"

#include "voxc/stages/Region.h"
#include "voxc/stages/StageKind.h"

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include <set>
#include <string>

namespace voxc::check {

namespace {

// Compiling a kernel costs milliseconds whatever its size, so a pipeline of thousands of distinct
// stages would compile for minutes: each field stage of a new (field, mode, material) is one
// kernel, each window size (sweep) of a grammar not run before another. Reported at the stage
// that passes Limits::maxKernels.
void checkKernelCount(Context& context, const Program& program) {
    std::set<std::string> seen;
    int64_t kernels = 0;
    for (const Stage& stage : program.pipeline) {
        kernels += stages::stageKind(stage.kind).newKernels(program, stage, seen);
        if (kernels <= context.limits.maxKernels) continue;
        // The default pipeline's grammar stages have no location of their own.
        const bool located = stage.loc.line != 0 || stage.kind != Stage::Kind::Grammar;
        context.diagnostics.error("E0012", located ? stage.loc : program.grammars[stage.index].loc,
                                  fmt::format("the pipeline needs {} kernels here, more than the limit of {} (a field "
                                              "stage of a new field, mode or material is one kernel, each window size "
                                              "of a grammar not run before one more)",
                                              kernels, context.limits.maxKernels));
        return;
    }
}

std::string formatCorner(glm::ivec3 v) { return fmt::format("{},{},{}", v.x, v.y, v.z); }

// A run of a region (CheckOptions::region) runs the box grown by the pipeline's halo, clipped to
// the world: that grid must fit Limits::maxVoxels (E0014 at the stage whose radius reaches
// farthest, or at no place when the box alone is too large). Returns the region's program, or
// nothing when there is no region to run (one outside the world is the driver's error).
std::optional<Program> regionRun(Context& context, const Program& program) {
    const auto [lo, hi] = *context.region;
    const stages::GridBox region{glm::max(lo - program.world.origin, glm::ivec3(0)),
                                 glm::min(hi - program.world.origin, program.world.size)};
    if (!glm::all(glm::lessThan(region.min, region.max))) return std::nullopt;
    const stages::PipelineHalo halo = stages::pipelineHalo(program);
    const stages::GridBox grid = stages::haloBox(program, region, halo.radius);
    const glm::ivec3 size = grid.size();
    const int64_t voxels = int64_t(size.x) * size.y * size.z;
    if (voxels <= context.limits.maxVoxels) return stages::regionProgram(program, grid);
    const glm::ivec3 asked = region.size();
    const int64_t askedVoxels = int64_t(asked.x) * asked.y * asked.z;
    if (askedVoxels > context.limits.maxVoxels) {
        context.diagnostics.error("E0014", {},
                                  fmt::format("the region {}:{} alone is a {}x{}x{} grid of {} voxels, more than the "
                                              "limit of {}; ask for a smaller region",
                                              formatCorner(lo), formatCorner(hi), asked.x, asked.y, asked.z,
                                              askedVoxels, context.limits.maxVoxels));
        return std::nullopt;
    }
    size_t farthest = 0;
    for (size_t i = 1; i < halo.stages.size(); ++i) {
        const glm::ivec3 r = halo.stages[i].radius, best = halo.stages[farthest].radius;
        if (r.x + r.y + r.z > best.x + best.y + best.z) farthest = i;
    }
    const Stage& stage = program.pipeline.at(farthest);
    const stages::StageRadius& radius = halo.stages.at(farthest);
    // The default pipeline's grammar stages have no location of their own.
    const SourceLoc loc = stage.loc.line != 0 || stage.kind != Stage::Kind::Grammar ? stage.loc
                                                                                   : program.grammars[stage.index].loc;
    context.diagnostics.error(
        "E0014", loc,
        fmt::format("the region {}:{} grown by the pipeline's halo [{}, {}, {}] is a {}x{}x{} grid of {} voxels, more "
                    "than the limit of {}; stage '{}' alone reaches [{}, {}, {}] voxels: {}; ask for a smaller region",
                    formatCorner(lo), formatCorner(hi), halo.radius.x, halo.radius.y, halo.radius.z, size.x, size.y,
                    size.z, voxels, context.limits.maxVoxels, stage.label, radius.radius.x, radius.radius.y,
                    radius.radius.z, radius.why));
    return std::nullopt;
}

} // namespace

void checkWork(Context& context, const Program& whole) {
    checkKernelCount(context, whole);
    std::optional<Program> region;
    if (context.region) {
        region = regionRun(context, whole);
        if (!region) return;
    }
    const Program& program = region ? *region : whole;
    const glm::ivec3 size = program.world.size;
    const double voxels = double(size.x) * size.y * size.z;
    const double budget = double(context.limits.maxWork);
    double total = 0.0;
    for (const Stage& stage : program.pipeline) {
        const stages::StageWork step = stages::stageKind(stage.kind).estimateWork(program, stage, voxels);
        if (total + step.work <= budget) {
            total += step.work;
            continue;
        }
        context.diagnostics.error(
            "E0012", step.loc,
            fmt::format("the pipeline's estimated work passes the budget of {} here: {} before this stage, plus {} "
                        "for {}; raise the budget with --max-work if this run is intended",
                        stages::formatWork(budget), stages::formatWork(total), stages::formatWork(step.work), step.what));
        return;
    }
}

} // namespace voxc::check
