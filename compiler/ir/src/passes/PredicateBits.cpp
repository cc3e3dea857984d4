#include "voxc/ir/passes/PredicateBits.h"

#include "voxc/builtins/Ops.h"

#include <algorithm>

namespace voxc::ir {

namespace {

// Two predicates are the same test when they have the same operator and, where the operator
// takes one, equal values (-0 and +0 compare alike, so they may share a bit).
bool sameTest(const Predicate& a, const Predicate& b) {
    return a.op == b.op && (!symbolOpInfo(a.op).takesValue || a.value == b.value);
}

uint32_t testBit(IrCell& cell, const Predicate& p) {
    for (uint32_t b = 0; b < cell.tests.size(); ++b)
        if (sameTest(cell.tests[b], p)) return b;
    cell.tests.push_back(p);
    return uint32_t(cell.tests.size() - 1);
}

} // namespace

IrModule assignPredicateBits(IrModule module) {
    for (IrGrammar& grammar : module.grammars) {
        for (IrSweep& sweep : grammar.sweeps) {
            for (IrCell& cell : sweep.cells)
                cell.tests.clear();
            for (IrRule& rule : sweep.rules) {
                rule.needs.assign(sweep.cells.size(), {});
                for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
                    std::vector<uint32_t>& needs = rule.needs[c];
                    for (const Predicate& p : rule.symbol[c].predicates)
                        if (p.op != SymbolOp::IGN) needs.push_back(testBit(sweep.cells[c], p));
                    std::sort(needs.begin(), needs.end());
                    needs.erase(std::unique(needs.begin(), needs.end()), needs.end());
                }
            }
        }
    }
    return module;
}

} // namespace voxc::ir
