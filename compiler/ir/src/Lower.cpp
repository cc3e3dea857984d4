#include "voxc/ir/Lower.h"

#include "voxc/ir/passes/BuildSweeps.h"
#include "voxc/ir/passes/DeadCells.h"
#include "voxc/ir/passes/PredicateBits.h"
#include "voxc/ir/passes/RemoveNeverMatchingRules.h"

#include <utility>

namespace voxc::ir {

IrModule lowerProgram(const Program& program, const LowerOptions& options) {
    auto after = [&](std::string_view name, const IrModule& module) {
        if (options.afterPass) options.afterPass(name, module);
    };
    IrModule module = buildSweeps(program);
    after("build-sweeps", module);
    // Rules go first so that the later passes see only what the kernels will evaluate.
    module = removeNeverMatchingRules(std::move(module));
    after("remove-never-matching-rules", module);
    module = assignPredicateBits(std::move(module));
    after("predicate-bits", module);
    module = eliminateDeadCells(std::move(module));
    after("dead-cells", module);
    return module;
}

} // namespace voxc::ir
