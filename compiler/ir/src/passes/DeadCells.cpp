#include "voxc/ir/passes/DeadCells.h"

#include "voxc/builtins/Ops.h"

namespace voxc::ir {

namespace {

// Whether writing this transform needs the cell's old density. The Ops registry has no such
// field, so the switch is here; -Wswitch flags a new operator.
bool transformReadsDensity(TransformOp op) {
    switch (op) {
    case TransformOp::NOP: return false;
    case TransformOp::SET: return false;
    case TransformOp::ADD: return true;
    }
    return true;
}

bool symbolReads(const SymbolCell& cell) {
    for (const Predicate& p : cell.predicates)
        if (p.op != SymbolOp::IGN) return true;
    return false;
}

} // namespace

IrModule eliminateDeadCells(IrModule module) {
    for (IrGrammar& grammar : module.grammars) {
        for (IrSweep& sweep : grammar.sweeps) {
            for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
                bool reads = false;
                bool writes = false;
                bool readsMaterial = false;
                for (const IrRule& rule : sweep.rules) {
                    const TransformCell& t = rule.transform[c];
                    reads = reads || symbolReads(rule.symbol[c]) || transformReadsDensity(t.op);
                    writes = writes || transformOpInfo(t.op).writes || t.material.has_value();
                    readsMaterial = readsMaterial || !rule.symbol[c].materialPredicates.empty();
                }
                // A cell whose material alone is read or written needs its address, not its density.
                sweep.cells[c].access = reads                     ? CellAccess::Load
                                        : writes || readsMaterial ? CellAccess::Address
                                                                  : CellAccess::None;
                sweep.cells[c].loadsMaterial = readsMaterial;
            }
        }
    }
    return module;
}

} // namespace voxc::ir
