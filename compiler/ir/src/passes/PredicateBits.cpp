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

// Index into IrCell::materialTests; its bit is tests.size() + the index.
uint32_t materialTestIndex(IrCell& cell, const MaterialPredicate& p) {
    for (uint32_t i = 0; i < cell.materialTests.size(); ++i)
        if (cell.materialTests[i].op == p.op && cell.materialTests[i].material == p.material) return i;
    cell.materialTests.push_back(p);
    return uint32_t(cell.materialTests.size() - 1);
}

} // namespace

IrModule assignPredicateBits(IrModule module) {
    for (IrGrammar& grammar : module.grammars) {
        for (IrSweep& sweep : grammar.sweeps) {
            for (IrCell& cell : sweep.cells) {
                cell.tests.clear();
                cell.materialTests.clear();
            }
            // Density tests take the low bits of every cell, so their numbering does not depend
            // on material tests; the material bits follow once every density test is known.
            std::vector<std::vector<std::vector<uint32_t>>> materialNeeds(sweep.rules.size());
            for (size_t r = 0; r < sweep.rules.size(); ++r) {
                IrRule& rule = sweep.rules[r];
                rule.needs.assign(sweep.cells.size(), {});
                materialNeeds[r].assign(sweep.cells.size(), {});
                for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
                    for (const Predicate& p : rule.symbol[c].predicates)
                        if (p.op != SymbolOp::IGN) rule.needs[c].push_back(testBit(sweep.cells[c], p));
                    for (const MaterialPredicate& p : rule.symbol[c].materialPredicates)
                        materialNeeds[r][c].push_back(materialTestIndex(sweep.cells[c], p));
                }
            }
            for (size_t r = 0; r < sweep.rules.size(); ++r) {
                for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
                    std::vector<uint32_t>& needs = sweep.rules[r].needs[c];
                    for (uint32_t m : materialNeeds[r][c]) needs.push_back(uint32_t(sweep.cells[c].tests.size()) + m);
                    std::sort(needs.begin(), needs.end());
                    needs.erase(std::unique(needs.begin(), needs.end()), needs.end());
                }
            }
        }
    }
    return module;
}

} // namespace voxc::ir
