#include "voxc/codegen/Codegen.h"

#include "KernelSources.h"
#include "voxc/codegen/Spirv.h"
#include "voxc/ir/Lower.h"
#include "voxc/program/Semantics.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <fmt/format.h>

namespace voxc::codegen {

namespace {

Kernel makeKernel(std::string name, std::string origin, const DispatchShape& shape, std::string glsl) {
    Kernel kernel;
    kernel.name = std::move(name);
    kernel.origin = std::move(origin);
    kernel.glsl = std::move(glsl);
    for (int a = 0; a < 3; ++a) {
        kernel.localSize[a] = shape.localSize[a];
        kernel.anchorsPerInvocation[a] = shape.anchorsPerInvocation[a];
    }
    kernel.spirv = compileComputeShader(kernel.name, kernel.glsl);
    return kernel;
}

SweepPlan planSweep(const Grammar& grammar, const ir::IrSweep& irSweep, uint32_t kernel) {
    Sweep sweep;
    sweep.window = irSweep.window;
    sweep.anchorCount = irSweep.anchorCount;
    sweep.phaseCount = irSweep.phaseCount;
    SweepPlan plan;
    plan.kernel = kernel;
    plan.window = irSweep.window;
    plan.phaseCount = irSweep.phaseCount;
    fillPhaseAnchors(plan, grammar, sweep);
    return plan;
}

} // namespace

KernelPackage compileProgram(const Program& program, const CompileOptions& options) {
    const ir::IrModule module = ir::lowerProgram(program, ir::LowerOptions{options.afterPass});
    const std::string sourceName =
        program.sourcePath.empty() ? "<program>" : std::filesystem::path(program.sourcePath).filename().string();

    KernelPackage package;
    package.world = program.world;
    package.kernels.push_back(
        makeKernel("start", fmt::format("{} start", sourceName), startDispatchShape(module),
                   startKernelSource(module, sourceName)));

    // One kernel per (field, mode) the pipeline runs, however often.
    std::map<std::pair<uint32_t, FieldMode>, std::vector<Stage>> fieldStages;
    for (const Stage& stage : module.pipeline)
        if (stage.kind == Stage::Kind::Field) fieldStages[{stage.index, stage.mode}].push_back(stage);
    std::map<std::pair<uint32_t, FieldMode>, uint32_t> fieldKernels;
    for (const auto& [key, stages] : fieldStages) {
        const ir::IrField& field = module.fields.at(key.first);
        const std::string name = fmt::format("{}_{}", field.name, ir::fieldModeName(key.second));
        const std::string origin = fmt::format("{}:{}:{} field {}, {}", sourceName, field.loc.line, field.loc.column,
                                               field.name, ir::fieldModeName(key.second));
        fieldKernels[key] = uint32_t(package.kernels.size());
        package.kernels.push_back(
            makeKernel(name, origin, fieldDispatchShape(module),
                       fieldKernelSource(module, field, key.second, stages, name, sourceName)));
    }

    // Kernels of a grammar are generated once, even if the pipeline runs it more than once.
    std::vector<GrammarPlan> grammarPlans;
    for (const ir::IrGrammar& grammar : module.grammars) {
        GrammarPlan plan;
        plan.name = grammar.name;
        plan.iterations = uint32_t(grammar.iterations);
        for (const ir::IrSweep& sweep : grammar.sweeps) {
            const std::string name = fmt::format("{}_sweep{}", grammar.name, sweep.index);
            const std::string origin =
                fmt::format("{}:{}:{} grammar {}, window [{},{},{}]", sourceName, grammar.loc.line, grammar.loc.column,
                            grammar.name, sweep.window.x, sweep.window.y, sweep.window.z);
            plan.sweeps.push_back(
                planSweep(program.grammars[grammar.programIndex], sweep, uint32_t(package.kernels.size())));
            package.kernels.push_back(makeKernel(name, origin, sweepDispatchShape(sweep),
                                                 sweepKernelSource(grammar, sweep, name, sourceName)));
        }
        grammarPlans.push_back(std::move(plan));
    }

    // The tile-skipping kernels follow the sweep kernels; a sweep without live rules needs none.
    for (size_t g = 0; g < module.grammars.size(); ++g) {
        const ir::IrGrammar& grammar = module.grammars[g];
        for (size_t s = 0; s < grammar.sweeps.size(); ++s) {
            const ir::IrSweep& sweep = grammar.sweeps[s];
            if (sweep.rules.empty()) continue;
            const std::string name = fmt::format("{}_sweep{}_active_tiles", grammar.name, sweep.index);
            const std::string origin = package.kernels[grammarPlans[g].sweeps[s].kernel].origin;
            grammarPlans[g].sweeps[s].activeTilesKernel = uint32_t(package.kernels.size());
            package.kernels.push_back(makeKernel(name, origin, activeTilesDispatchShape(),
                                                 activeTilesKernelSource(grammar, sweep, name, sourceName)));
        }
    }
    if (!module.grammars.empty()) {
        package.tileRangesKernel = uint32_t(package.kernels.size());
        package.kernels.push_back(makeKernel("tile_ranges", "voxc runtime: tile density ranges",
                                             tileRangesDispatchShape(), tileRangesKernelSource()));
    }

    // Every density is 0 before the pipeline; the start stage writes only its shapes' values.
    // After a grammar or field stage the bounds are not tracked.
    std::optional<DensityBounds> densities = DensityBounds{};
    for (const Stage& stage : module.pipeline) {
        StagePlan plan;
        plan.kind = stage.kind;
        switch (stage.kind) {
        case Stage::Kind::Start:
            plan.startKernel = 0;
            if (densities)
                for (const StartShape& shape : module.start)
                    densities = DensityBounds{std::min(densities->lo, shape.value), std::max(densities->hi, shape.value)};
            break;
        case Stage::Kind::Grammar:
            plan.grammar = grammarPlans.at(stage.index);
            densities.reset();
            break;
        case Stage::Kind::Field:
            plan.fieldKernel = fieldKernels.at({stage.index, stage.mode});
            plan.fieldName = module.fields.at(stage.index).name;
            plan.fieldMode = stage.mode;
            plan.fieldBoxes = fieldBoxes(module, module.fields.at(stage.index), stage.mode, densities);
            densities.reset();
            break;
        }
        package.stages.push_back(std::move(plan));
    }
    return package;
}

} // namespace voxc::codegen
