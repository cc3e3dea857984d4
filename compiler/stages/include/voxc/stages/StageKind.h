#pragma once
// A pipeline stage kind is one record: how the checker describes and bounds it, how the
// interpreter runs it, and how it lowers to kernels and dispatches, side by side in one file
// per kind (src/kinds/). The passes and backends ask the record; none switches on the kind.
// Adding a kind: a Stage::Kind value, its record file, and one line in StageKinds.cpp.
#include "voxc/codegen/KernelPackage.h"
#include "voxc/codegen/KernelSources.h"
#include "voxc/grid/Grid.h"
#include "voxc/grid/NonFinite.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/ir/Ir.h"
#include "voxc/program/Program.h"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace voxc::stages {

// A stage's share of the pipeline's work estimate (docs/language.md, "Work estimate").
struct StageWork {
    double work = 0.0;
    SourceLoc loc;    // where an over-budget message points
    std::string what; // how the work is made up, for that message
};

// How far a voxel's value after a stage can depend on the grid before it: every grid voxel
// within `radius` of it per axis (a box), the farthest such voxel found on some grid. 0 for a
// pure function of position; capped at world size - 1 (the whole world along that axis, e.g. a
// column stage's y). Regions and tiles compute a halo of the pipeline's sum (voxc/stages/Region.h).
struct StageRadius {
    glm::ivec3 radius{0};
    std::string why; // how it is made up, for `voxc check --explain-halo`
};

// What the records share while one package is built.
struct PlanContext {
    const Program& program;
    const ir::IrModule& module;
    std::string sourceName; // the .vox file's name, as generated comments spell it
    KernelPackage& package;
    // Bounds of every density before the stage being planned; empty once unknown.
    std::optional<codegen::DensityBounds> densities;
    // Kernels by a key each record chooses, so a kernel several stages run is built once.
    std::map<std::string, uint32_t> kernels;

    // Compiles `glsl` to a kernel of the package and returns its index.
    uint32_t addKernel(std::string name, std::string origin, const codegen::DispatchShape& shape, std::string glsl);
};

struct StageKind {
    Stage::Kind kind;
    std::string_view name; // the manifest's "kind"

    // Checking, from the checked program alone.
    std::string (*label)(const Program& program, const Stage& stage); // the pipeline entry as written
    bool (*readsDensities)(const Stage& stage);
    bool (*writesMaterials)(const Program& program, const Stage& stage);
    StageWork (*estimateWork)(const Program& program, const Stage& stage, double voxels);
    // Kernels the stage adds to those `seen` keys name (Limits::maxKernels); records its keys there.
    int64_t (*newKernels)(const Program& program, const Stage& stage, std::set<std::string>& seen);
    StageRadius (*dependencyRadius)(const Program& program, const Stage& stage);

    // Interpretation: runs the stage on the grid in place.
    void (*interpret)(const Program& program, const Stage& stage, DenseGrid& grid, const InterpOptions& options,
                      NonFiniteCount* nonFinite);

    // Lowering: adds the kind's kernels for the whole pipeline (once per package, in registry
    // order, so kernel order is stable), then fills one stage's plan.
    void (*addKernels)(PlanContext& context);
    void (*plan)(PlanContext& context, const Stage& stage, StagePlan& plan);
};

// Every kind, in registry order.
std::vector<const StageKind*> stageKinds();
const StageKind& stageKind(Stage::Kind kind);

// A stage of `kind` with the facts every pass reads (Stage::label, readsDensities,
// writesMaterials) filled from its record: how the checker and tests make stages.
Stage makeStage(const Program& program, Stage::Kind kind, uint32_t index, FieldMode mode = FieldMode::Set,
                SourceLoc loc = {}, std::optional<uint8_t> material = std::nullopt);
// Fills those facts of every stage of program.pipeline.
void describePipeline(Program& program);

// Work estimates reach far beyond int64 (iterations x anchors x rules x cells); doubles keep the
// order of magnitude, which is all a budget needs. Printed with three digits.
std::string formatWork(double work);

} // namespace voxc::stages
