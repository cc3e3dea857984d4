#include "Kinds.h"

#include "voxc/core/Errors.h"

#include <array>
#include <fmt/format.h>

namespace voxc::stages {

namespace {

const std::array<const StageKind*, 5> kKinds = {&kStartStage, &kGrammarStage, &kFieldStage, &kSpeleothemStage, &kCurvesStage};

} // namespace

std::vector<const StageKind*> stageKinds() { return {kKinds.begin(), kKinds.end()}; }

const StageKind& stageKind(Stage::Kind kind) {
    for (const StageKind* record : kKinds)
        if (record->kind == kind) return *record;
    throw InternalError(fmt::format("no record for stage kind {}", int(kind)));
}

Stage makeStage(const Program& program, Stage::Kind kind, uint32_t index, FieldMode mode, SourceLoc loc,
                std::optional<uint8_t> material) {
    Stage stage{kind, index, mode, loc, material};
    const StageKind& record = stageKind(kind);
    stage.label = record.label(program, stage);
    stage.readsDensities = record.readsDensities(stage);
    stage.writesMaterials = record.writesMaterials(program, stage);
    return stage;
}

void describePipeline(Program& program) {
    for (Stage& stage : program.pipeline)
        stage = makeStage(program, stage.kind, stage.index, stage.mode, stage.loc, stage.material);
}

std::string formatWork(double work) { return fmt::format("{:.3g}", work); }

uint32_t PlanContext::addKernel(std::string name, std::string origin, const codegen::DispatchShape& shape,
                                std::string glsl) {
    package.kernels.push_back(
        codegen::makeKernel(std::move(name), std::move(origin), shape, std::move(glsl), package.usesMaterials));
    return uint32_t(package.kernels.size() - 1);
}

} // namespace voxc::stages
