#include "voxc/stages/Pipeline.h"
#include "voxc/stages/StageKind.h"

namespace voxc {

DenseGrid interpret(const Program& program, const InterpOptions& options) {
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
