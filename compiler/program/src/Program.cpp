#include "voxc/program/Program.h"

#include <algorithm>

namespace voxc {

bool Program::usesMaterials() const {
    const auto startWrites = std::any_of(start.begin(), start.end(), [](const StartShape& s) { return s.material.has_value(); });
    const auto stageWrites = std::any_of(pipeline.begin(), pipeline.end(), [](const Stage& s) { return s.material.has_value(); });
    const auto grammarUses = std::any_of(grammars.begin(), grammars.end(), [](const Grammar& g) {
        return std::any_of(g.rules.begin(), g.rules.end(), [](const Rule& rule) {
            const bool tests = std::any_of(rule.symbol.begin(), rule.symbol.end(),
                                           [](const SymbolCell& c) { return !c.materialPredicates.empty(); });
            const bool writes = std::any_of(rule.transform.begin(), rule.transform.end(),
                                            [](const TransformCell& c) { return c.material.has_value(); });
            const bool stamps = std::any_of(rule.stamps.begin(), rule.stamps.end(),
                                            [](const Stamp& s) { return s.material.has_value(); });
            return tests || writes || stamps;
        });
    });
    // A curves stage writes the materials of its constraint points (SolveTable::material).
    const auto curvesWrite = std::any_of(pipeline.begin(), pipeline.end(), [this](const Stage& s) {
        return s.kind == Stage::Kind::Curves && curves.at(s.index).writesMaterials;
    });
    return startWrites || stageWrites || grammarUses || curvesWrite;
}

const Material* Program::findMaterial(uint8_t id) const {
    const auto it = std::find_if(materials.begin(), materials.end(), [id](const Material& m) { return m.id == id; });
    return it == materials.end() ? nullptr : &*it;
}

} // namespace voxc
