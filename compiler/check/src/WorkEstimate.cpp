// The pipeline's work estimate against Limits::maxWork: every stage adds what running it costs,
// in the same units for both backends (one window cell tested, one shape or DAG node evaluated
// at one voxel), and the stage at which the sum passes the budget is reported.
#include "Sections.h"
#include "Values.h"

#include "voxc/program/Semantics.h"

#include <fmt/format.h>

#include <set>
#include <tuple>

namespace voxc::check {

namespace {

// Estimates reach far beyond int64 (iterations x anchors x rules x cells); doubles keep the
// order of magnitude, which is all a budget needs.
std::string formatWork(double work) { return fmt::format("{:.3g}", work); }

// One iteration of a grammar: every sweep tests each rule's cells at each anchor.
double grammarIterationWork(const Grammar& grammar) {
    double work = 0.0;
    for (const Sweep& sweep : orderSweeps(grammar)) {
        const double anchors = double(sweep.anchorCount.x) * sweep.anchorCount.y * sweep.anchorCount.z;
        const double cells = double(sweep.window.x) * sweep.window.y * sweep.window.z;
        work += anchors * double(sweep.rules.size()) * cells;
    }
    return work;
}

struct StageWork {
    double work = 0.0;
    SourceLoc loc;
    std::string what; // how the stage's work is made up, for the message
};

StageWork stageWork(const Program& program, const Stage& stage, double voxels) {
    switch (stage.kind) {
    case Stage::Kind::Start: {
        const double shapes = double(program.start.size());
        SourceLoc loc = program.start.empty() ? stage.loc : program.start.back().loc;
        return {shapes * voxels, loc,
                fmt::format("the start state ({} shapes x {} voxels)", program.start.size(), formatWork(voxels))};
    }
    case Stage::Kind::Grammar: {
        const Grammar& grammar = program.grammars[stage.index];
        const double perIteration = grammarIterationWork(grammar);
        return {perIteration * grammar.iterations, stage.loc.line ? stage.loc : grammar.loc,
                fmt::format("grammar '{}' ({} iterations x {} window cells tested per iteration: anchors x rules x "
                            "cells over its sweeps)",
                            grammar.name, grammar.iterations, formatWork(perIteration))};
    }
    case Stage::Kind::Field: {
        const Field& field = program.fields[stage.index];
        return {voxels * double(field.nodes.size()), stage.loc,
                fmt::format("field '{}' ({} voxels x {} nodes)", field.name, formatWork(voxels), field.nodes.size())};
    }
    }
    return {};
}

// Compiling a kernel costs milliseconds whatever its size, so a pipeline of thousands of distinct
// stages would compile for minutes: each field stage of a new (field, mode, material) is one
// kernel, each window size (sweep) of a grammar not run before another. Reported at the stage
// that passes Limits::maxKernels.
void checkKernelCount(Context& context, const Program& program) {
    std::set<std::tuple<uint32_t, FieldMode, int>> fieldStages;
    std::set<uint32_t> grammars;
    int64_t kernels = 0;
    for (const Stage& stage : program.pipeline) {
        const int material = stage.material ? int(*stage.material) : -1;
        if (stage.kind == Stage::Kind::Field && fieldStages.emplace(stage.index, stage.mode, material).second)
            kernels += 1;
        else if (stage.kind == Stage::Kind::Grammar && grammars.insert(stage.index).second)
            kernels += int64_t(orderSweeps(program.grammars[stage.index]).size());
        else
            continue;
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
        const StageWork step = stageWork(program, stage, voxels);
        if (total + step.work <= budget) {
            total += step.work;
            continue;
        }
        context.diagnostics.error(
            "E0012", step.loc,
            fmt::format("the pipeline's estimated work passes the budget of {} here: {} before this stage, plus {} "
                        "for {}; raise the budget with --max-work if this run is intended",
                        formatWork(budget), formatWork(total), formatWork(step.work), step.what));
        return;
    }
}

} // namespace voxc::check
