#include "voxc/ir/Lower.h"

#include "voxc/ir/passes/BuildSweeps.h"
#include "voxc/ir/passes/DeadCells.h"
#include "voxc/ir/passes/EliminateCommonSubexpressions.h"
#include "voxc/ir/passes/FoldConstants.h"
#include "voxc/ir/passes/HoistColumnValues.h"
#include "voxc/ir/passes/PredicateBits.h"
#include "voxc/ir/passes/RemoveDeadStages.h"
#include "voxc/ir/passes/RemoveNeverMatchingRules.h"

#include "voxc/core/Errors.h"

#include <utility>

namespace voxc::ir {

IrModule lowerProgram(const Program& program, const LowerOptions& options) {
    // The passes read each stage's facts, which its kind's record fills (stages::describePipeline).
    for (const Stage& stage : program.pipeline)
        if (stage.label.empty()) throw InternalError("lowering a pipeline stage its record has not described");
    auto after = [&](std::string_view name, const IrModule& module) {
        if (options.afterPass) options.afterPass(name, module);
    };
    IrModule module = buildSweeps(program);
    for (const Field& field : program.fields)
        module.fields.push_back(IrField{field.name, field.loc, field.nodes, field.root, {}});
    after("build-sweeps", module);
    module = removeDeadStages(std::move(module));
    after("remove-dead-stages", module);
    // Rules go first so that the later passes see only what the kernels will evaluate.
    module = removeNeverMatchingRules(std::move(module));
    after("remove-never-matching-rules", module);
    module = assignPredicateBits(std::move(module));
    after("predicate-bits", module);
    module = eliminateDeadCells(std::move(module));
    after("dead-cells", module);
    module = foldConstants(std::move(module));
    after("fold-constants", module);
    // Folding leaves unused nodes and equal constants behind.
    module = eliminateCommonSubexpressions(std::move(module));
    after("eliminate-common-subexpressions", module);
    module = hoistColumnValues(std::move(module));
    after("hoist-column-values", module);
    return module;
}

} // namespace voxc::ir
