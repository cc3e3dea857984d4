#include "voxc/ir/passes/BuildSweeps.h"

#include "voxc/program/Semantics.h"

namespace voxc::ir {

namespace {

IrRule lowerRule(const Rule& rule, uint32_t ruleIndex) {
    IrRule out;
    out.ruleIndex = ruleIndex;
    out.name = rule.name;
    out.loc = rule.loc;
    out.priority = rule.priority;
    out.weightUnits = rule.weightUnits;
    out.probabilityUnits = rule.probabilityUnits;
    out.symbol = rule.symbol;
    out.transform = rule.transform;
    out.aggregates = rule.aggregates;
    out.stamps = rule.stamps;
    return out;
}

IrGrammar lowerGrammar(const Grammar& grammar, uint32_t programIndex) {
    IrGrammar out;
    out.name = grammar.name;
    out.loc = grammar.loc;
    out.programIndex = programIndex;
    out.stride = grammar.stride;
    out.boundsMin = grammar.boundsMin;
    out.boundsMax = grammar.boundsMax;
    out.iterations = grammar.iterations;
    out.clampMin = grammar.clampMin;
    out.clampMax = grammar.clampMax;
    const std::vector<Sweep> sweeps = orderSweeps(grammar);
    for (uint32_t s = 0; s < sweeps.size(); ++s) {
        IrSweep sweep;
        sweep.index = s;
        sweep.window = sweeps[s].window;
        sweep.anchorCount = sweeps[s].anchorCount;
        sweep.phaseCount = sweeps[s].phaseCount;
        const uint32_t cellCount = uint32_t(sweep.window.x * sweep.window.y * sweep.window.z);
        sweep.cells.resize(cellCount);
        for (uint32_t c = 0; c < cellCount; ++c)
            sweep.cells[c].offset = cellOffset(sweep.window, c);
        for (uint32_t r : sweeps[s].rules)
            sweep.rules.push_back(lowerRule(grammar.rules[r], r));
        out.sweeps.push_back(std::move(sweep));
    }
    return out;
}

} // namespace

IrModule buildSweeps(const Program& program) {
    IrModule module;
    module.sourcePath = program.sourcePath;
    module.world = program.world;
    module.start = program.start;
    module.pipeline = program.pipeline;
    for (uint32_t g = 0; g < program.grammars.size(); ++g)
        module.grammars.push_back(lowerGrammar(program.grammars[g], g));
    return module;
}

} // namespace voxc::ir
