#include "voxc/codegen/PointSets.h"
#include "voxc/codegen/SampledMaps.h"
#include "voxc/ir/Lower.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Solve.h"
#include "voxc/stages/StageKind.h"

#include <filesystem>
#include <glm/common.hpp>
#include <optional>

namespace voxc {

KernelPackage compileProgram(const Program& given, const CompileOptions& options) {
    std::optional<Program> solved;
    const Program& program = stages::solvedProgram(given, solved);
    const ir::IrModule module = ir::lowerProgram(program, ir::LowerOptions{options.afterPass});
    KernelPackage package;
    package.world = program.world;
    package.usesMaterials = program.usesMaterials();
    package.materials = program.materials;
    package.pointSets = codegen::pointSetsOf(module);
    // The sampled maps first: field kernels name map i as solve table i; stages add theirs after.
    for (const auto& map : codegen::mapsOf(module)) package.solveTables.push_back(codegen::mapTable(*map));
    stages::PlanContext context{
        program, module,
        program.sourcePath.empty() ? "<program>" : std::filesystem::path(program.sourcePath).filename().string(),
        package,
        // Every density is 0 before the pipeline.
        codegen::DensityBounds{},
        {}};
    for (const stages::StageKind* kind : stages::stageKinds()) kind->addKernels(context);
    for (const Stage& stage : module.pipeline) {
        const stages::StageKind& kind = stages::stageKind(stage.kind);
        StagePlan plan;
        plan.kind = kind.name;
        plan.loc = stage.loc;
        plan.label = stage.label;
        plan.material = stage.material;
        kind.plan(context, stage, plan);
        plan.dependencyRadius = kind.dependencyRadius(program, stage).radius;
        package.halo = glm::min(package.halo + plan.dependencyRadius, program.world.size - 1);
        package.stages.push_back(std::move(plan));
    }
    return package;
}

} // namespace voxc
