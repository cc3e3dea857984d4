// The start stage: the start block's shapes written over an all-air grid by one kernel.
#include "Kinds.h"

#include <algorithm>
#include <fmt/format.h>

namespace voxc::stages {

namespace {

std::string label(const Program&, const Stage&) { return "start"; }

// The start state replaces every voxel, so nothing before it matters.
bool readsDensities(const Stage&) { return false; }

bool writesMaterials(const Program& program, const Stage&) {
    return std::any_of(program.start.begin(), program.start.end(),
                       [](const StartShape& shape) { return shape.material.has_value(); });
}

StageWork estimateWork(const Program& program, const Stage& stage, double voxels) {
    const double shapes = double(program.start.size());
    const SourceLoc loc = program.start.empty() ? stage.loc : program.start.back().loc;
    return {shapes * voxels, loc,
            fmt::format("the start state ({} shapes x {} voxels)", program.start.size(), formatWork(voxels))};
}

// Compiling the start kernel is not counted against Limits::maxKernels: every program has one.
int64_t newKernels(const Program&, const Stage&, std::set<std::string>&) { return 0; }

// Every shape is a function of the voxel's position (the heightfield of its world x and z).
StageRadius dependencyRadius(const Program&, const Stage&) {
    return {glm::ivec3(0), "each voxel's shapes are functions of its position alone"};
}

// Shape values are finite literals within +-1e6 (E0007), so nothing is replaced.
void interpret(const Program& program, const Stage&, DenseGrid& grid, const InterpOptions&, NonFiniteCount*) {
    grid = evaluateStart(program);
}

// No start kernel when remove-dead-stages dropped the start stage (a later `set` overwrites it).
void addKernels(PlanContext& context) {
    const auto& pipeline = context.module.pipeline;
    if (std::none_of(pipeline.begin(), pipeline.end(), [](const Stage& s) { return s.kind == Stage::Kind::Start; }))
        return;
    context.kernels["start"] =
        context.addKernel("start", fmt::format("{} start", context.sourceName),
                          codegen::startDispatchShape(context.module),
                          codegen::startKernelSource(context.module, context.sourceName));
}

// Every density is 0 before the pipeline; the start stage writes only its shapes' values.
void plan(PlanContext& context, const Stage&, StagePlan& plan) {
    plan.gridKernel = context.kernels.at("start");
    plan.writesEveryDensity = true;
    if (context.densities)
        for (const StartShape& shape : context.module.start)
            context.densities = codegen::DensityBounds{std::min(context.densities->lo, shape.value),
                                                       std::max(context.densities->hi, shape.value)};
}

} // namespace

const StageKind kStartStage{Stage::Kind::Start, "start", label,     readsDensities, writesMaterials, estimateWork,
                            newKernels,         dependencyRadius, interpret, addKernels, plan};

} // namespace voxc::stages
