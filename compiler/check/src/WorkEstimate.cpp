// The pipeline's work estimate against Limits::maxWork: every stage adds what running it costs,
// in the same units for both backends (one window cell tested, one shape or DAG node evaluated
// at one voxel), and the stage at which the sum passes the budget is reported.
#include "Sections.h"
#include "Values.h"

#include "voxc/stages/StageKind.h"

#include <fmt/format.h>

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

} // namespace

void checkWork(Context& context, const Program& program) {
    checkKernelCount(context, program);
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
