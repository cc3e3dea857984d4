#include "voxc/codegen/KernelSources.h"
#include "voxc/codegen/Template.h"

#include "voxc/builtins/Ops.h"
#include "voxc/core/Errors.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace voxc::codegen {

namespace {

using ir::IrRule;
using ir::IrSweep;
using ir::printCell;
using ir::printPredicate;

// tiles.glsl densityKey: a < b implies densityKey(a) < densityKey(b).
uint32_t densityKey(float v) {
    const uint32_t bits = std::bit_cast<uint32_t>(v);
    return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
}

// The keys of the lowest and highest density in `interval`. An infinite end stays open to the
// extreme key, which also takes in the NaNs beyond it (only NEQ passes NaN, and its set
// reaches both infinities). -0 and +0 are equal densities with different keys, so a closed end
// at zero takes in both.
struct KeyInterval {
    uint32_t lo, hi;
};
KeyInterval keyInterval(const ValueInterval& interval) {
    constexpr float inf = std::numeric_limits<float>::infinity();
    KeyInterval k{0u, 0xffffffffu};
    if (interval.lo != -inf) {
        const float lowest = interval.loClosed ? (interval.lo == 0.0f ? -0.0f : interval.lo)
                                               : std::nextafter(interval.lo, inf);
        k.lo = densityKey(lowest);
    }
    if (interval.hi != inf) {
        const float highest = interval.hiClosed ? (interval.hi == 0.0f ? 0.0f : interval.hi)
                                                : std::nextafter(interval.hi, -inf);
        k.hi = densityKey(highest);
    }
    return k;
}

bool inBox(const AggregateTest& test, glm::ivec3 cell) {
    return glm::all(glm::greaterThanEqual(cell, test.boxMin)) && glm::all(glm::lessThan(cell, test.boxMax));
}

// An aggregate test that bounds every cell of its box: a `min` in [low, high] passes only when no
// cell but a NaN is below low (voxc::aggregatePasses skips later NaNs, and a NaN fails at the
// first cell), a `max` only when none is above high. The other kinds bound no single cell.
bool boundsCells(const AggregateTest& test) {
    return test.kind == AggregateKind::Min || test.kind == AggregateKind::Max;
}

// The densities window cell c can hold when the rule matches: every predicate of its symbol cell
// passes, and every `min` (`max`) test whose box holds it has it at least low (at most high).
// NaN keys lie beyond both infinities' (keyInterval), so those ranges stay open to them.
ValueSet cellValues(const IrRule& rule, uint32_t c, glm::ivec3 offset) {
    ValueSet set = ValueSet::all();
    for (const Predicate& p : rule.symbol[c].predicates)
        if (p.op != SymbolOp::IGN) set = set.intersect(symbolOpInfo(p.op).accepts(p.value));
    for (const AggregateTest& test : rule.aggregates)
        if (boundsCells(test) && inBox(test, offset))
            set = set.intersect(test.kind == AggregateKind::Min ? ValueSet::above(test.low, true)
                                                                : ValueSet::below(test.high, true));
    return set;
}

bool testsCell(const IrRule& rule, uint32_t c, glm::ivec3 offset) {
    for (const Predicate& p : rule.symbol[c].predicates)
        if (p.op != SymbolOp::IGN) return true;
    return std::any_of(rule.aggregates.begin(), rule.aggregates.end(),
                       [&](const AggregateTest& test) { return boundsCells(test) && inBox(test, offset); });
}

// Tiles track density ranges only: a material test is taken to pass, so skipping stays
// conservative, and a write of a material alone leaves every range valid.
bool testsMaterial(const IrRule& rule) {
    for (const SymbolCell& cell : rule.symbol)
        if (!cell.materialPredicates.empty()) return true;
    return false;
}

// Tiles are never smaller than this (voxc::skipTileShift).
constexpr int kMinTileSize = 8;

// `mayMatch`: some live rule has every tested cell's value set meeting its cell's range.
std::string mayMatch(const IrSweep& sweep) {
    std::string s = "// The density range each tested cell can read (keys), over this tile's anchors.\n";
    std::vector<bool> tested(sweep.cells.size(), false);
    for (const IrRule& rule : sweep.rules)
        for (uint32_t c = 0; c < sweep.cells.size(); ++c)
            tested[c] = tested[c] || testsCell(rule, c, sweep.cells[c].offset);
    // Offsets below the smallest tile size read only the anchors' tile and its next neighbours.
    bool near = true;
    for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
        const glm::ivec3 o = sweep.cells[c].offset;
        if (tested[c]) near = near && std::min({o.x, o.y, o.z}) >= 0 && std::max({o.x, o.y, o.z}) < kMinTileSize;
    }
    if (near) s += "TileNeighbourhood neighbourhood = tileNeighbourhood(tileOfId(id));\n";
    for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
        if (!tested[c]) continue;
        const glm::ivec3 o = sweep.cells[c].offset;
        s += near ? fmt::format("uvec2 range{} = nearCellRange(neighbourhood, anchors, ivec3({}, {}, {}));\n", c, o.x, o.y, o.z)
                  : fmt::format("uvec2 range{} = cellRange(anchors, ivec3({}, {}, {}));\n", c, o.x, o.y, o.z);
    }
    s += "\n// A rule may match when each of its tested cells' value sets meets that cell's range.\n";
    s += "bool mayMatch = false;\n";
    for (uint32_t r = 0; r < sweep.rules.size(); ++r) {
        const IrRule& rule = sweep.rules[r];
        std::vector<std::string> cells;
        for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
            if (!testsCell(rule, c, sweep.cells[c].offset)) continue;
            const ValueSet set = cellValues(rule, c, sweep.cells[c].offset);
            if (set.empty()) {
                // A `min`/`max` box no density passes with the cell's predicates: never matches.
                cells.push_back(fmt::format("false // {} no density passes its predicates and tests",
                                            printCell(sweep.cells[c].offset)));
                continue;
            }
            std::vector<std::string> meets;
            for (const ValueInterval& interval : set.intervals()) {
                const KeyInterval k = keyInterval(interval);
                meets.push_back(fmt::format("meets(range{}, 0x{:08x}u, 0x{:08x}u)", c, k.lo, k.hi));
            }
            std::vector<std::string> predicates;
            for (const Predicate& p : rule.symbol[c].predicates)
                if (p.op != SymbolOp::IGN) predicates.push_back(printPredicate(p));
            if (!rule.symbol[c].materialPredicates.empty()) predicates.push_back("(material tests may pass)");
            for (const AggregateTest& test : rule.aggregates)
                if (boundsCells(test) && inBox(test, sweep.cells[c].offset))
                    predicates.push_back(fmt::format("(where {})", ir::printAggregate(test)));
            cells.push_back(fmt::format("{} // {} {}", meets.size() == 1 ? meets[0] : fmt::format("({})", fmt::join(meets, " || ")),
                                        printCell(sweep.cells[c].offset), fmt::join(predicates, " & ")));
        }
        s += fmt::format("// {}: {}\n", r, rule.name);
        if (cells.empty()) {
            s += testsMaterial(rule) ? "mayMatch = true; // material tests only, which tiles do not track\n"
                                     : "mayMatch = true; // every cell IGN: matches everywhere\n";
            continue;
        }
        s += "mayMatch = mayMatch ||\n";
        for (size_t i = 0; i < cells.size(); ++i) {
            const size_t comment = cells[i].find(" //");
            s += fmt::format("    {}{}{}\n", cells[i].substr(0, comment), i + 1 == cells.size() ? ";" : " &&",
                             cells[i].substr(comment));
        }
    }
    return s;
}

} // namespace

DispatchShape activeTilesDispatchShape() { return DispatchShape{{64, 1, 1}, {1, 1, 1}}; }

std::string activeTilesKernelSource(const ir::IrGrammar& grammar, const IrSweep& sweep, std::string_view kernelName,
                                     std::string_view sourceName) {
    VOXC_ASSERT(!sweep.rules.empty());
    const std::string header =
        fmt::format("voxc generated kernel \"{}\": the active tiles of each phase of sweep {} (window {}) of\n"
                    "grammar {} ({}:{}:{}).\n",
                    kernelName, sweep.index, ir::printVec(sweep.window), grammar.name, sourceName, grammar.loc.line,
                    grammar.loc.column);
    const DispatchShape sweepShape = sweepDispatchShape(sweep);
    const uint32_t invocations = sweepShape.localSize[0] * sweepShape.localSize[1] * sweepShape.localSize[2];
    return instantiateTemplate(
        "active_tiles.glsl",
        {{"HEADER", prefixLines(header, "// ")},
         {"DISPATCH_SHAPE", dispatchShapeGlsl(activeTilesDispatchShape())},
         {"SWEEP_SHAPE", fmt::format("// Invocations in one workgroup of the sweep kernel.\n"
                                     "const int SWEEP_WORKGROUP_INVOCATIONS = {};\n",
                                     invocations)},
         {"MAY_MATCH", mayMatch(sweep)}});
}

DispatchShape tileRangesDispatchShape() { return DispatchShape{{64, 1, 1}, {1, 1, 1}}; }

std::string tileRangesKernelSource() { return instantiateTemplate("tile_ranges.glsl", {}); }

} // namespace voxc::codegen
