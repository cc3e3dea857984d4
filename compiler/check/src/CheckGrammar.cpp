// `grammar NAME { ... }` blocks and their rules.
#include "CheckAggregates.h"
#include "CheckStamps.h"
#include "Layout.h"
#include "Sections.h"
#include "Suggest.h"
#include "voxc/check/KeyRanges.h"
#include "Symmetry.h"
#include "Values.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <map>

namespace voxc::check {

namespace {

constexpr int64_t kInt32Min = std::numeric_limits<int32_t>::min();
constexpr int64_t kInt32Max = std::numeric_limits<int32_t>::max();

// A declared rule and, when it has a `symmetry` key, the elements it is expanded by.
struct DeclaredRule {
    CheckedRule checked;
    std::optional<std::vector<SymmetryElement>> symmetry;
};

// The `symbol` or `transform` block of a rule: exactly one (E0009 when missing, E0003 twice).
const ast::Block* findPart(Context& context, const ast::Block& rule, std::string_view part, const std::string& where) {
    const ast::Block* found = nullptr;
    for (const ast::Block& block : rule.blocks) {
        if (block.kind != part) continue;
        if (found) {
            context.diagnostics.error("E0003", block.loc, fmt::format("{} has two '{}' blocks", where, part),
                                      {{found->loc, "first one here"}});
            continue;
        }
        found = &block;
    }
    if (!found) context.diagnostics.error("E0009", rule.loc, fmt::format("{} is missing its '{}' block", where, part));
    return found;
}

bool convertSymbol(Context& context, const ast::Block& block, CheckedRule& out) {
    auto cells = readLayout(context, block, out.rule.size);
    if (!cells) return false;
    bool ok = true;
    for (const ast::Cell* cell : *cells) {
        auto converted = convertSymbolCell(context, *cell);
        ok = ok && converted.has_value();
        out.rule.symbol.push_back(converted.value_or(SymbolCell{}));
        out.syntax.symbolCells.push_back(cell->loc);
    }
    return ok;
}

bool convertTransform(Context& context, const ast::Block& block, CheckedRule& out) {
    auto cells = readLayout(context, block, out.rule.size);
    if (!cells) return false;
    bool ok = true;
    for (const ast::Cell* cell : *cells) {
        auto converted = convertTransformCell(context, *cell);
        ok = ok && converted.has_value();
        out.rule.transform.push_back(converted.value_or(TransformCell{}));
    }
    return ok;
}

void readWeight(Context& context, const ast::Assignment& a, Rule& rule) {
    auto weight = readNumber(context, a, 0.0, 1000.0);
    if (!weight) return;
    const double units = std::round(*weight * kWeightUnitsPerOne);
    if (units < 1.0) {
        context.diagnostics.error("E0007", a.value.loc,
                                  fmt::format("'weight' must be greater than 0 (at least 0.0005, one "
                                              "thousandth after rounding), got {}",
                                              formatNumber(*weight)));
        return;
    }
    rule.weight = float(*weight);
    rule.weightUnits = uint32_t(units);
}

std::optional<DeclaredRule> checkRule(Context& context, const ast::Block& block) {
    static constexpr std::string_view kKeys[] = {"size", "priority", "weight", "probability", "symmetry"};
    static constexpr std::string_view kParts[] = {"symbol", "transform", "where", "stamp"};
    if (!checkLabel(context, block, true)) return std::nullopt;
    const std::string where = fmt::format("rule '{}'", *block.label);
    rejectUnexpectedMembers(context, block, where, {.blocks = true});
    BlockKeys keys(context, block, where, kKeys);
    for (const ast::Block& part : block.blocks)
        if (std::find(std::begin(kParts), std::end(kParts), part.kind) == std::end(kParts))
            context.diagnostics.error("E0008", part.loc,
                                      fmt::format("unknown block '{}' in {}{}", part.kind, where,
                                                  didYouMean(part.kind, kParts)));
    const int errorsBefore = context.diagnostics.errorCount();

    DeclaredRule declared;
    CheckedRule& out = declared.checked;
    out.rule.name = *block.label;
    out.rule.loc = block.labelLoc;
    bool sizeOk = false;
    if (const ast::Assignment* a = keys.require("size")) {
        out.syntax.sizeLoc = a->value.loc;
        if (auto size = readIntegerVec3(context, *a, 1, int64_t(1) << 20)) {
            const int64_t cells = int64_t(size->x) * size->y * size->z;
            if (cells > context.limits.maxWindowCells)
                context.diagnostics.error("E0012", a->value.loc,
                                          fmt::format("a {} window has {} cells, more than the limit of {}",
                                                      formatVec(*size), cells, context.limits.maxWindowCells));
            else {
                out.rule.size = *size;
                sizeOk = true;
            }
        }
    }
    if (const ast::Assignment* a = keys.find("priority")) {
        const KeyRange range = *grammarKeyRange("rule", "priority");
        if (auto priority = readInteger(context, *a, int64_t(range.min), int64_t(range.max)))
            out.rule.priority = int32_t(*priority);
    }
    if (const ast::Assignment* a = keys.find("weight")) readWeight(context, *a, out.rule);
    if (const ast::Assignment* a = keys.find("probability")) {
        const KeyRange range = *grammarKeyRange("rule", "probability");
        if (auto probability = readNumber(context, *a, range.min, range.max)) {
            out.rule.probability = float(*probability);
            out.rule.probabilityUnits = uint32_t(std::round(*probability * double(kProbabilityOne)));
        }
    }
    if (const ast::Assignment* a = keys.find("symmetry")) declared.symmetry = readSymmetry(context, *a);
    const ast::Block* symbol = findPart(context, block, "symbol", where);
    const ast::Block* transform = findPart(context, block, "transform", where);
    if (symbol) out.syntax.symbolLoc = symbol->loc;
    if (sizeOk && symbol) convertSymbol(context, *symbol, out);
    if (sizeOk && transform) convertTransform(context, *transform, out);
    for (const ast::Block& part : block.blocks)
        if (part.kind == "where" && sizeOk)
            for (const AggregateTest& test : checkWhereBlock(context, part, out.rule.size, where))
                out.rule.aggregates.push_back(test);
    for (const ast::Block& part : block.blocks) {
        if (part.kind != "stamp" || !sizeOk) continue;
        SourceLoc reachLoc, offsetLoc;
        if (auto stamp = checkStampBlock(context, part, out.rule.size, where, reachLoc, offsetLoc)) {
            out.rule.stamps.push_back(std::move(*stamp));
            out.syntax.stampReachLocs.push_back(reachLoc);
            out.syntax.stampOffsetLocs.push_back(offsetLoc);
        }
    }

    if (context.diagnostics.errorCount() != errorsBefore) return std::nullopt;
    return declared;
}

// Bounds default to the whole grid and must lie inside it (nothing is clipped silently).
void readBounds(Context& context, const ast::Assignment& a, const World* world, Grammar& grammar) {
    auto box = readBox(context, a);
    if (!box) return;
    const auto [lo, hi] = *box;
    for (int axis = 0; axis < 3; ++axis) {
        if (lo[axis] < hi[axis]) continue;
        context.diagnostics.error("E0007", a.value.loc,
                                  fmt::format("'bounds' are empty along {}: min {} is not below max {}", "xyz"[axis],
                                              lo[axis], hi[axis]));
        return;
    }
    if (world) {
        const glm::ivec3 size = world->size;
        bool inside = lo.x >= 0 && lo.y >= 0 && lo.z >= 0 && hi.x <= size.x && hi.y <= size.y && hi.z <= size.z;
        if (!inside) {
            context.diagnostics.error("E0007", a.value.loc,
                                      fmt::format("'bounds' [{}, {}] reach outside the grid [[0, 0, 0], {}]",
                                                  formatVec(lo), formatVec(hi), formatVec(size)));
            return;
        }
    }
    grammar.boundsMin = lo;
    grammar.boundsMax = hi;
}

// Rules of one size form one sweep, compiled into one kernel that tests every cell of every
// rule, so both the rule count and rules x cells are bounded; each is reported once per size,
// at the rule that passes it.
void checkSweepSizes(Context& context, const ast::Block& block, const Grammar& grammar) {
    std::map<std::tuple<int, int, int>, int> rulesPerSize;
    for (const Rule& rule : grammar.rules) {
        const int count = ++rulesPerSize[{rule.size.x, rule.size.y, rule.size.z}];
        const int64_t cells = int64_t(rule.size.x) * rule.size.y * rule.size.z;
        const int64_t cellLimit = context.limits.maxSweepRuleCells;
        if (count == context.limits.maxRulesPerSweep + 1)
            context.diagnostics.error("E0012", block.labelLoc,
                                      fmt::format("grammar '{}' has more than {} rules of size {}", grammar.name,
                                                  context.limits.maxRulesPerSweep, formatVec(rule.size)));
        else if (count * cells > cellLimit && (count - 1) * cells <= cellLimit)
            context.diagnostics.error(
                "E0012", rule.loc,
                fmt::format("grammar '{}' has {} rules of size {} with this one: {} x {} window cells is more than "
                            "the limit of {} per sweep (the size of its kernel)",
                            grammar.name, count, formatVec(rule.size), count, cells, cellLimit));
    }
}

} // namespace

std::optional<CheckedGrammar> checkGrammar(Context& context, const ast::Block& block, const World* world) {
    static constexpr std::string_view kKeys[] = {"stride", "bounds", "iterations", "clamp", "symmetry"};
    static constexpr std::string_view kBlocks[] = {"rule"};
    if (!checkLabel(context, block, true)) return std::nullopt;
    const std::string where = fmt::format("grammar '{}'", *block.label);
    rejectUnexpectedMembers(context, block, where, {.blocks = true});
    BlockKeys keys(context, block, where, kKeys);
    const int errorsBefore = context.diagnostics.errorCount();

    CheckedGrammar out;
    Grammar& grammar = out.grammar;
    grammar.name = *block.label;
    grammar.loc = block.labelLoc;
    if (world) grammar.boundsMax = world->size;
    if (const ast::Assignment* a = keys.find("stride"))
        if (auto stride = readIntegerVec3(context, *a, 1, kInt32Max)) grammar.stride = *stride;
    if (const ast::Assignment* a = keys.find("bounds")) readBounds(context, *a, world, grammar);
    if (const ast::Assignment* a = keys.find("iterations")) {
        if (auto iterations = readInteger(context, *a, 1, kInt32Max)) {
            if (*iterations > context.limits.maxIterations)
                context.diagnostics.error("E0012", a->value.loc,
                                          fmt::format("{} iterations is more than the limit of {}", *iterations,
                                                      context.limits.maxIterations));
            else
                grammar.iterations = int32_t(*iterations);
        }
    }
    if (const ast::Assignment* a = keys.find("clamp")) {
        if (auto range = readRange(context, *a)) {
            grammar.clampMin = float((*range)[0]);
            grammar.clampMax = float((*range)[1]);
        }
    }

    std::vector<SymmetryElement> grammarSymmetry = *symmetryGroup("none");
    if (const ast::Assignment* a = keys.find("symmetry"))
        if (auto elements = readSymmetry(context, *a)) grammarSymmetry = std::move(*elements);

    std::map<std::string, SourceLoc> ruleNames;
    size_t declaredRules = 0;
    for (const ast::Block& ruleBlock : block.blocks) {
        if (ruleBlock.kind != "rule") {
            context.diagnostics.error("E0008", ruleBlock.loc,
                                      fmt::format("unknown block '{}' in {}{}", ruleBlock.kind, where,
                                                  didYouMean(ruleBlock.kind, kBlocks)));
            continue;
        }
        if (ruleBlock.label) {
            auto [it, inserted] = ruleNames.emplace(*ruleBlock.label, ruleBlock.labelLoc);
            if (!inserted)
                context.diagnostics.error("E0003", ruleBlock.labelLoc,
                                          fmt::format("{} already has a rule named '{}'", where, *ruleBlock.label),
                                          {{it->second, "first declared here"}});
        }
        if (auto rule = checkRule(context, ruleBlock)) {
            rule->checked.syntax.declaredIndex = declaredRules++;
            for (CheckedRule& variant : expandSymmetry(rule->checked, rule->symmetry.value_or(grammarSymmetry))) {
                grammar.rules.push_back(std::move(variant.rule));
                out.rules.push_back(std::move(variant.syntax));
            }
        }
    }
    if (block.blocks.empty())
        context.diagnostics.error("E0009", block.labelLoc, fmt::format("{} has no rules", where));
    checkSweepSizes(context, block, grammar);
    checkStampOverlap(context, grammar, out.rules);

    if (context.diagnostics.errorCount() != errorsBefore) return std::nullopt;
    return out;
}

} // namespace voxc::check
