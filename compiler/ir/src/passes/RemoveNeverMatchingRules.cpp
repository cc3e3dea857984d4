#include "voxc/ir/passes/RemoveNeverMatchingRules.h"

#include "voxc/builtins/Ops.h"

#include <optional>

namespace voxc::ir {

namespace {

// A cell whose predicates together accept no density, if the rule has one.
std::optional<uint32_t> impossibleCell(const IrRule& rule) {
    for (uint32_t c = 0; c < rule.symbol.size(); ++c) {
        ValueSet passing = ValueSet::all();
        for (const Predicate& p : rule.symbol[c].predicates)
            passing = passing.intersect(symbolOpInfo(p.op).accepts(p.value));
        if (passing.empty()) return c;
    }
    return std::nullopt;
}

} // namespace

IrModule removeNeverMatchingRules(IrModule module) {
    for (IrGrammar& grammar : module.grammars) {
        for (IrSweep& sweep : grammar.sweeps) {
            std::vector<IrRule> live;
            for (IrRule& rule : sweep.rules) {
                if (const std::optional<uint32_t> cell = impossibleCell(rule))
                    sweep.removed.push_back(IrRemovedRule{rule.ruleIndex, rule.name, rule.loc, *cell});
                else
                    live.push_back(std::move(rule));
            }
            sweep.rules = std::move(live);
        }
    }
    return module;
}

} // namespace voxc::ir
