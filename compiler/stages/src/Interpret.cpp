#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Solve.h"
#include "voxc/stages/StageKind.h"

#include <optional>

namespace voxc {

DenseGrid interpret(const Program& given, const InterpOptions& options) {
    std::optional<Program> solved;
    const Program& program = stages::solvedProgram(given, solved);
    DenseGrid grid(program.world.size);
    if (options.nonFinite) options.nonFinite->assign(program.pipeline.size(), NonFiniteCount{});
    for (size_t i = 0; i < program.pipeline.size(); ++i) {
        const Stage& stage = program.pipeline[i];
        NonFiniteCount* nonFinite = options.nonFinite ? &(*options.nonFinite)[i] : nullptr;
        stages::stageKind(stage.kind).interpret(program, stage, grid, options, nonFinite);
    }
    return grid;
}

} // namespace voxc
