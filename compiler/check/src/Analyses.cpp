// Warnings about rules that are legal but almost certainly not what the author meant.
// Each symbol cell is turned into the set of densities and the set of materials it accepts
// (ValueSet, from the operator registry; a bitset of the 256 ids), which makes "never matches"
// and "can match together" exact questions.
#include "Sections.h"
#include "Values.h"

#include "voxc/builtins/Ops.h"
#include "voxc/builtins/ValueSet.h"

#include <bitset>
#include <fmt/format.h>
#include <glm/vector_relational.hpp>
#include <set>

namespace voxc::check {

namespace {

using MaterialSet = std::bitset<256>;

// What one symbol cell accepts; it passes for some voxel exactly when both sets are non-empty,
// since density and material are independent.
struct CellSet {
    ValueSet densities = ValueSet::all();
    MaterialSet materials = MaterialSet().set();

    bool empty() const { return densities.empty() || materials.none(); }
    CellSet intersect(const CellSet& other) const {
        return {densities.intersect(other.densities), materials & other.materials};
    }
};

CellSet acceptedValues(const SymbolCell& cell) {
    CellSet set;
    for (const Predicate& predicate : cell.predicates)
        set.densities = set.densities.intersect(symbolOpInfo(predicate.op).accepts(predicate.value));
    for (const MaterialPredicate& predicate : cell.materialPredicates) {
        MaterialSet accepted;
        for (size_t id = 0; id < accepted.size(); ++id)
            accepted[id] = materialOpInfo(predicate.op).eval(uint8_t(id), predicate.material);
        set.materials &= accepted;
    }
    return set;
}

// "row 2, column 1" in the printed layout (first row = top), plus the layer when there are several.
std::string printedPosition(glm::ivec3 size, int x, int y, int z) {
    std::string position = fmt::format("row {}, column {}", size.y - y, x + 1);
    if (size.z > 1) position += fmt::format(" of layer {}", z + 1);
    return position;
}

// W0201 and W0202. Returns whether the rule can match at all.
bool analyseSymbol(Context& context, const Rule& rule, const RuleSyntax& syntax,
                   const std::vector<CellSet>& cellSets) {
    bool allIgnore = true;
    for (const SymbolCell& cell : rule.symbol)
        allIgnore = allIgnore && cell.predicates.empty() && cell.materialPredicates.empty();
    if (allIgnore && rule.aggregates.empty()) // a `where` block makes an all-IGN symbol selective
        context.diagnostics.warning("W0201", syntax.symbolLoc,
                                    fmt::format("the symbol of rule '{}' is all IGN, so it matches every window "
                                                "inside the bounds",
                                                rule.name));
    bool canMatch = true;
    const glm::ivec3 size = rule.size;
    for (int z = 0; z < size.z; ++z)
        for (int y = size.y - 1; y >= 0; --y)
            for (int x = 0; x < size.x; ++x) {
                const int index = cellIndex(size, x, y, z);
                if (!cellSets[index].empty()) continue;
                canMatch = false;
                const char* what = cellSets[index].densities.empty() ? "density" : "material";
                context.diagnostics.warning("W0202", syntax.symbolCells[index],
                                            fmt::format("rule '{}' can never match: no {} passes every "
                                                        "predicate of the cell at {}",
                                                        rule.name, what, printedPosition(size, x, y, z)));
            }
    return canMatch;
}

bool canMatchTogether(const std::vector<CellSet>& a, const std::vector<CellSet>& b) {
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].intersect(b[i]).empty()) return false;
    return true;
}

} // namespace

void analyseGrammar(Context& context, const CheckedGrammar& checked) {
    const Grammar& grammar = checked.grammar;
    std::vector<std::vector<CellSet>> sets(grammar.rules.size());
    std::vector<bool> canMatch(grammar.rules.size());
    for (size_t r = 0; r < grammar.rules.size(); ++r) {
        const Rule& rule = grammar.rules[r];
        for (const SymbolCell& cell : rule.symbol) sets[r].push_back(acceptedValues(cell));
        // A variant matches exactly when its original does (the same cells, moved): say it once.
        canMatch[r] = checked.rules[r].isVariant ? canMatch[r - 1]
                                                 : analyseSymbol(context, rule, checked.rules[r], sets[r]);

        const glm::ivec3 extent = grammar.boundsMax - grammar.boundsMin;
        if (glm::any(glm::greaterThan(rule.size, extent)))
            context.diagnostics.warning("W0204", checked.rules[r].sizeLoc,
                                        fmt::format("rule '{}' has a {} window, which never fits inside the "
                                                    "bounds of grammar '{}' (extent {}), so it never runs",
                                                    rule.name, formatVec(rule.size), grammar.name,
                                                    formatVec(extent)));
    }
    // W0203: only rules of one size share a sweep, and only equal priorities leave the choice to weights.
    // Variants of one declared rule overlapping is what symmetry asks for; other pairs are
    // reported once per pair of declared rules.
    std::set<std::pair<size_t, size_t>> reportedPairs;
    for (size_t b = 0; b < grammar.rules.size(); ++b)
        for (size_t a = 0; a < b; ++a) {
            const Rule& first = grammar.rules[a];
            const Rule& second = grammar.rules[b];
            if (first.size != second.size || first.priority != second.priority || !canMatch[a] || !canMatch[b])
                continue;
            const std::pair declaredPair{checked.rules[a].declaredIndex, checked.rules[b].declaredIndex};
            if (declaredPair.first == declaredPair.second || reportedPairs.count(declaredPair)) continue;
            if (!canMatchTogether(sets[a], sets[b])) continue;
            reportedPairs.insert(declaredPair);
            context.diagnostics.warning("W0203", second.loc,
                                        fmt::format("rules '{}' and '{}' have the same size and priority and can "
                                                    "both match the same window; their weights decide which fires",
                                                    first.name, second.name),
                                        {{first.loc, fmt::format("rule '{}' is declared here", first.name)}});
        }
}

} // namespace voxc::check
