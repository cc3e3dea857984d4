#include "voxc/codegen/Codegen.h"

#include "KernelSources.h"
#include "voxc/codegen/Spirv.h"
#include "voxc/core/Errors.h"
#include "voxc/ir/Lower.h"
#include "voxc/program/Semantics.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <tuple>
#include <fmt/format.h>

namespace voxc::codegen {

namespace {

// Every kernel of a package that uses materials is compiled with VOXC_MATERIALS, so
// common.glsl declares the material buffer (kBindingMaterials).
std::string withMaterials(std::string glsl) {
    const size_t lineEnd = glsl.find('\n');
    VOXC_ASSERT(glsl.starts_with("#version") && lineEnd != std::string::npos);
    return glsl.insert(lineEnd + 1, "#define VOXC_MATERIALS\n");
}

// How kernel names spell a material: its declared name, `none` for id 0.
std::string materialName(const Program& program, uint8_t id) {
    if (const Material* declared = program.findMaterial(id)) return declared->name;
    return id == kMaterialNone ? "none" : fmt::format("material{}", id);
}

Kernel makeKernel(std::string name, std::string origin, const DispatchShape& shape, std::string glsl,
                  bool usesMaterials) {
    Kernel kernel;
    kernel.name = std::move(name);
    kernel.origin = std::move(origin);
    kernel.glsl = usesMaterials ? withMaterials(std::move(glsl)) : std::move(glsl);
    for (int a = 0; a < 3; ++a) {
        kernel.localSize[a] = shape.localSize[a];
        kernel.anchorsPerInvocation[a] = shape.anchorsPerInvocation[a];
    }
    kernel.spirv = compileComputeShader(kernel.name, kernel.glsl);
    kernel.bindings = spirvDescriptorBindings(kernel.spirv);
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
    package.usesMaterials = program.usesMaterials();
    package.materials = program.materials;
    const auto makePackageKernel = [&](std::string name, std::string origin, const DispatchShape& shape,
                                       std::string glsl) {
        return makeKernel(std::move(name), std::move(origin), shape, std::move(glsl), package.usesMaterials);
    };
    // No start kernel when remove-dead-stages dropped the start stage (a later `set` overwrites it).
    const bool runsStart = std::any_of(module.pipeline.begin(), module.pipeline.end(),
                                       [](const Stage& stage) { return stage.kind == Stage::Kind::Start; });
    const uint32_t startKernel = uint32_t(package.kernels.size());
    if (runsStart)
        package.kernels.push_back(makePackageKernel("start", fmt::format("{} start", sourceName),
                                                    startDispatchShape(module), startKernelSource(module, sourceName)));

    // One kernel per (field, mode, material) the pipeline runs, however often; the material is
    // part of the kernel ("<field>_<mode>_<material>").
    using FieldKey = std::tuple<uint32_t, FieldMode, std::optional<uint8_t>>;
    std::map<FieldKey, std::vector<Stage>> fieldStages;
    for (const Stage& stage : module.pipeline)
        if (stage.kind == Stage::Kind::Field) fieldStages[{stage.index, stage.mode, stage.material}].push_back(stage);
    std::map<FieldKey, uint32_t> fieldKernels;
    for (const auto& [key, stages] : fieldStages) {
        const auto& [fieldIndex, mode, material] = key;
        const ir::IrField& field = module.fields.at(fieldIndex);
        std::string name = fmt::format("{}_{}", field.name, ir::fieldModeName(mode));
        if (material) name += "_" + materialName(program, *material);
        const std::string origin = fmt::format("{}:{}:{} field {}, {}", sourceName, field.loc.line, field.loc.column,
                                               field.name, ir::fieldModeName(mode));
        fieldKernels[key] = uint32_t(package.kernels.size());
        package.kernels.push_back(
            makePackageKernel(name, origin, fieldDispatchShape(module),
                              fieldKernelSource(module, field, mode, material, stages, name, sourceName)));
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
            package.kernels.push_back(makePackageKernel(name, origin, sweepDispatchShape(sweep),
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
            package.kernels.push_back(makePackageKernel(name, origin, activeTilesDispatchShape(),
                                                        activeTilesKernelSource(grammar, sweep, name, sourceName)));
        }
    }
    if (!module.grammars.empty()) {
        package.tileRangesKernel = uint32_t(package.kernels.size());
        package.kernels.push_back(makePackageKernel("tile_ranges", "voxc runtime: tile density ranges",
                                                    tileRangesDispatchShape(), tileRangesKernelSource()));
    }

    // Every density is 0 before the pipeline; the start stage writes only its shapes' values; a
    // field stage's bounds follow from the field's interval bounds. After a grammar they are not
    // tracked.
    std::optional<DensityBounds> densities = DensityBounds{};
    for (const Stage& stage : module.pipeline) {
        StagePlan plan;
        plan.kind = stage.kind;
        plan.loc = stage.loc;
        switch (stage.kind) {
        case Stage::Kind::Start:
            plan.startKernel = startKernel;
            if (densities)
                for (const StartShape& shape : module.start)
                    densities = DensityBounds{std::min(densities->lo, shape.value), std::max(densities->hi, shape.value)};
            break;
        case Stage::Kind::Grammar:
            plan.grammar = grammarPlans.at(stage.index);
            densities.reset();
            break;
        case Stage::Kind::Field:
            plan.fieldKernel = fieldKernels.at({stage.index, stage.mode, stage.material});
            plan.fieldName = module.fields.at(stage.index).name;
            plan.fieldMode = stage.mode;
            plan.fieldMaterial = stage.material;
            FieldStageBoxes boxes = fieldBoxes(module, module.fields.at(stage.index), stage.mode, stage.material, densities);
            plan.fieldBoxes = std::move(boxes.boxes);
            densities = boxes.after;
            break;
        }
        package.stages.push_back(std::move(plan));
    }
    return package;
}

} // namespace voxc::codegen
