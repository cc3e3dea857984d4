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
    const double stageCount = double(program.pipeline.size());
    for (size_t i = 0; i < program.pipeline.size(); ++i) {
        const Stage& stage = program.pipeline[i];
        NonFiniteCount* nonFinite = options.nonFinite ? &(*options.nonFinite)[i] : nullptr;
        if (!options.progress) {
            stages::stageKind(stage.kind).interpret(program, stage, grid, options, nonFinite);
            continue;
        }
        // The stage's own fractions (a grammar's iterations) become the pipeline's.
        InterpOptions stageOptions = options;
        stageOptions.progress = [&options, i, stageCount](double f) { options.progress((double(i) + f) / stageCount); };
        stageOptions.progress(0.0);
        stages::stageKind(stage.kind).interpret(program, stage, grid, stageOptions, nonFinite);
    }
    if (options.progress) options.progress(1.0);
    return grid;
}

} // namespace voxc
