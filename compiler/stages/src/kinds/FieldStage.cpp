// A field stage: the field's value combined with every voxel (set, union, subtract, intersect,
// paint), by one column-walking kernel per (field, mode, material), dispatched once per box of
// the chunks interval analysis classified.
#include "Kinds.h"

#include "voxc/interp/FieldEval.h"

#include <algorithm>
#include <fmt/format.h>

namespace voxc::stages {

namespace {

std::string label(const Program& program, const Stage& stage) {
    return fmt::format("{} {}", ir::fieldModeName(stage.mode), program.fields.at(stage.index).name);
}

// combineField's set writes f, and its material test looks at f alone.
bool readsDensities(const Stage& stage) { return stage.mode != FieldMode::Set; }

bool writesMaterials(const Program&, const Stage& stage) { return stage.material.has_value(); }

StageWork estimateWork(const Program& program, const Stage& stage, double voxels) {
    const Field& field = program.fields[stage.index];
    return {voxels * double(field.nodes.size()), stage.loc,
            fmt::format("field '{}' ({} voxels x {} nodes)", field.name, formatWork(voxels), field.nodes.size())};
}

// How kernel names spell a material: its declared name, `none` for id 0.
std::string materialName(const Program& program, uint8_t id) {
    if (const Material* declared = program.findMaterial(id)) return declared->name;
    return id == kMaterialNone ? "none" : fmt::format("material{}", id);
}

// "<field>_<mode>[_<material>]": also the kernel's key, so each (field, mode, material) is one kernel.
std::string kernelName(const Program& program, const std::string& field, const Stage& stage) {
    std::string name = fmt::format("{}_{}", field, ir::fieldModeName(stage.mode));
    if (stage.material) name += "_" + materialName(program, *stage.material);
    return name;
}

int64_t newKernels(const Program& program, const Stage& stage, std::set<std::string>& seen) {
    return seen.insert(kernelName(program, program.fields[stage.index].name, stage)).second ? 1 : 0;
}

// A field is a function of position (point sets and features were made when the file was checked).
StageRadius dependencyRadius(const Program&, const Stage&) {
    return {glm::ivec3(0), "the field is a function of position, combined with the voxel's own density"};
}

void interpret(const Program& program, const Stage& stage, DenseGrid& grid, const InterpOptions& options,
               NonFiniteCount* nonFinite) {
    runField(program, stage, grid, nonFinite, options.progress);
}

// In (field, mode, material) order, whatever the pipeline order, so kernel order is stable.
void addKernels(PlanContext& context) {
    using Key = std::tuple<uint32_t, FieldMode, std::optional<uint8_t>>;
    std::map<Key, std::vector<Stage>> stagesOf;
    for (const Stage& stage : context.module.pipeline)
        if (stage.kind == Stage::Kind::Field) stagesOf[{stage.index, stage.mode, stage.material}].push_back(stage);
    for (const auto& [key, stages] : stagesOf) {
        const auto& [fieldIndex, mode, material] = key;
        const ir::IrField& field = context.module.fields.at(fieldIndex);
        const std::string name = kernelName(context.program, field.name, stages.front());
        const std::string origin = fmt::format("{}:{}:{} field {}, {}", context.sourceName, field.loc.line,
                                               field.loc.column, field.name, ir::fieldModeName(mode));
        context.kernels[name] = context.addKernel(
            name, origin, codegen::fieldDispatchShape(context.module, field),
            codegen::fieldKernelSource(context.module, field, mode, material, stages, name, context.sourceName));
    }
}

// The field's interval bounds give the stage's boxes and the densities after it.
void plan(PlanContext& context, const Stage& stage, StagePlan& plan) {
    const ir::IrField& field = context.module.fields.at(stage.index);
    plan.gridKernel = context.kernels.at(kernelName(context.program, field.name, stage));
    plan.attributes.emplace_back("field", field.name);
    plan.attributes.emplace_back("mode", std::string(ir::fieldModeName(stage.mode)));
    plan.writesDensities = stage.mode != FieldMode::Paint;
    codegen::FieldStageBoxes boxes =
        codegen::fieldBoxes(context.module, field, stage.mode, stage.material, context.densities);
    plan.gridBoxes = std::move(boxes.boxes);
    plan.writesEveryDensity = !readsDensities(stage) && std::none_of(plan.gridBoxes.begin(), plan.gridBoxes.end(),
                                                                     [](const FieldBox& box) { return box.unchanged; });
    context.densities = boxes.after;
}

} // namespace

const StageKind kFieldStage{Stage::Kind::Field, "field", label,     readsDensities, writesMaterials, estimateWork,
                            newKernels,         dependencyRadius, interpret, addKernels, plan};

} // namespace voxc::stages
