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
#include <set>

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

// Where a cell of a matching window must lie against the occupancy level (tiles.glsl).
enum class LevelSide { Any, Holds, Fails };

// A NaN passes a cell's predicates only when each of them passes it (NEQ does), and NaN never
// holds the level; `min`/`max` tests skip NaN cells, so they cannot rule it out.
bool passesNaN(const IrRule& rule, uint32_t c) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    return std::all_of(rule.symbol[c].predicates.begin(), rule.symbol[c].predicates.end(), [&](const Predicate& p) {
        return p.op == SymbolOp::IGN || symbolOpInfo(p.op).eval(nan, p.value);
    });
}

LevelSide levelSide(const IrRule& rule, uint32_t c, glm::ivec3 offset, const OccupancyLevel& level) {
    if (!testsCell(rule, c, offset)) return LevelSide::Any;
    const ValueSet values = cellValues(rule, c, offset);
    if (values.intersect(ValueSet::above(level.value, !level.strict)).empty()) return LevelSide::Fails;
    if (values.intersect(ValueSet::below(level.value, level.strict)).empty() && !passesNaN(rule, c))
        return LevelSide::Holds;
    return LevelSide::Any;
}

// Whether a sweep's tested cells all lie below the smallest tile size from the anchor: then a
// tile's anchors read only that tile and its next ones (nearCellRange, occupancyRow).
bool nearCells(const IrSweep& sweep) {
    for (const IrRule& rule : sweep.rules)
        for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
            const glm::ivec3 o = sweep.cells[c].offset;
            if (testsCell(rule, c, o) && (std::min({o.x, o.y, o.z}) < 0 || std::max({o.x, o.y, o.z}) >= kMinTileSize))
                return false;
        }
    return true;
}

// The range tests of one rule: each tested cell's value set meets that cell's range.
std::string rangeTest(const IrSweep& sweep, const IrRule& rule) {
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
    if (cells.empty()) return "";
    std::string s;
    for (size_t i = 0; i < cells.size(); ++i) {
        const size_t comment = cells[i].find(" //");
        s += fmt::format("    {}{}{}\n", cells[i].substr(0, comment), i + 1 == cells.size() ? ";" : " &&",
                         cells[i].substr(comment));
    }
    return s;
}

// The row variable holding the occupancy bits of window row (dy, dz) at the current anchor row.
std::string rowName(glm::ivec3 offset) { return fmt::format("row_{}_{}", offset.y, offset.z); }

// A rule's occupancy pattern over the anchors of one anchor row, as a uint expression (a bit
// per anchor x), or "" when the level decides none of its cells; adds the window rows (z, y) it
// reads to `rows`.
std::string patternTest(const IrSweep& sweep, const IrRule& rule, const OccupancyLevel& level,
                        std::set<std::pair<int, int>>& rows) {
    std::vector<std::string> terms;
    for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
        const glm::ivec3 o = sweep.cells[c].offset;
        const LevelSide side = levelSide(rule, c, o, level);
        if (side == LevelSide::Any) continue;
        terms.push_back(fmt::format("({}{} >> {})", side == LevelSide::Holds ? "" : "~", rowName(o), o.x));
        rows.insert({o.z, o.y});
    }
    if (terms.empty()) return "";
    return fmt::format("anchorsX & {}", fmt::join(terms, " & "));
}

// `mayMatch`: some live rule has every tested cell's value set meeting its cell's range and,
// where the occupancy level decides some of its cells, its pattern of cells holding and failing
// the level occurs at an anchor of this phase in the tile.
std::string mayMatch(const IrSweep& sweep, const std::optional<OccupancyLevel>& level) {
    std::string s = "// The density range each tested cell can read (keys), over this tile's anchors.\n";
    std::vector<bool> tested(sweep.cells.size(), false);
    for (const IrRule& rule : sweep.rules)
        for (uint32_t c = 0; c < sweep.cells.size(); ++c)
            tested[c] = tested[c] || testsCell(rule, c, sweep.cells[c].offset);
    // Offsets below the smallest tile size read only the anchors' tile and its next neighbours.
    const bool near = nearCells(sweep);
    if (near) s += "TileNeighbourhood neighbourhood = tileNeighbourhood(tileOfId(id));\n";
    for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
        if (!tested[c]) continue;
        const glm::ivec3 o = sweep.cells[c].offset;
        s += near ? fmt::format("uvec2 range{} = nearCellRange(neighbourhood, anchors, ivec3({}, {}, {}));\n", c, o.x, o.y, o.z)
                  : fmt::format("uvec2 range{} = cellRange(anchors, ivec3({}, {}, {}));\n", c, o.x, o.y, o.z);
    }

    s += "\n// A rule may match when each of its tested cells' value sets meets that cell's range.\n";
    s += "bool mayMatch = false;\n";
    std::vector<std::string> patterns(sweep.rules.size());
    std::set<std::pair<int, int>> rows; // the window rows (z, y) the patterns read, from the anchor row
    for (uint32_t r = 0; r < sweep.rules.size(); ++r) {
        const IrRule& rule = sweep.rules[r];
        const std::string ranges = rangeTest(sweep, rule);
        if (near && level) patterns[r] = patternTest(sweep, rule, *level, rows);
        s += fmt::format("// {}: {}\n", r, rule.name);
        if (ranges.empty()) {
            s += testsMaterial(rule) ? "mayMatch = true; // material tests only, which tiles do not track\n"
                                     : "mayMatch = true; // every cell IGN: matches everywhere\n";
            continue;
        }
        if (patterns[r].empty()) {
            s += "mayMatch = mayMatch ||\n" + ranges;
        } else {
            s += fmt::format("bool ranges{} =\n{}", r, ranges);
            s += fmt::format("mayMatch = mayMatch || (ranges{} && !occupancyTracked());\n", r);
        }
    }
    if (rows.empty()) return s; // no rule has a pattern

    std::vector<std::string> candidates;
    for (uint32_t r = 0; r < sweep.rules.size(); ++r)
        if (!patterns[r].empty()) candidates.push_back(fmt::format("ranges{}", r));
    s += "\n// Rules whose ranges pass and whose cells the occupancy level decides: look for their\n"
         "// patterns of voxels holding (row bits) and failing it (~) at this phase's anchors, a row\n"
         "// of anchors at a time (bit x: the anchor at tile-local x).\n";
    s += fmt::format("if (!mayMatch && ({})) {{\n", fmt::join(candidates, " || "));
    s += "    ivec3 localStart = push.gridOrigin.xyz + push.anchorStart.xyz - neighbourhood.tile * tileSize();\n"
         "    uint anchorsX = 0u;\n"
         "    for (int i = anchors.first.x; i <= anchors.last.x; ++i) anchorsX |= 1u << (localStart.x + i * push.anchorStep.x);\n"
         "    for (int iz = anchors.first.z; iz <= anchors.last.z && !mayMatch; ++iz) {\n"
         "        int z = localStart.z + iz * push.anchorStep.z;\n"
         "        for (int iy = anchors.first.y; iy <= anchors.last.y && !mayMatch; ++iy) {\n"
         "            int y = localStart.y + iy * push.anchorStep.y;\n";
    for (const auto& [dz, dy] : rows)
        s += fmt::format("            uint {} = occupancyRow(neighbourhood, y + {}, z + {});\n",
                         rowName(glm::ivec3(0, dy, dz)), dy, dz);
    for (uint32_t r = 0; r < sweep.rules.size(); ++r)
        if (!patterns[r].empty())
            s += fmt::format("            mayMatch = mayMatch || (ranges{} && ({}) != 0u); // {}\n", r, patterns[r],
                             sweep.rules[r].name);
    s += "        }\n    }\n}\n";
    return s;
}

// Candidate levels of a cell: the ends of its value set's intervals.
void addCandidates(const ValueSet& values, std::set<std::pair<float, bool>>& out) {
    for (const ValueInterval& interval : values.intervals()) {
        if (std::isfinite(interval.lo)) out.insert({interval.lo, !interval.loClosed});
        if (std::isfinite(interval.hi)) out.insert({interval.hi, interval.hiClosed});
    }
}

} // namespace

DispatchShape activeTilesDispatchShape() { return DispatchShape{{64, 1, 1}, {1, 1, 1}}; }

std::optional<OccupancyLevel> occupancyLevel(const ir::IrModule& module) {
    std::set<std::pair<float, bool>> candidates;
    for (const ir::IrGrammar& grammar : module.grammars)
        for (const IrSweep& sweep : grammar.sweeps)
            for (const IrRule& rule : sweep.rules)
                for (uint32_t c = 0; c < sweep.cells.size(); ++c)
                    if (testsCell(rule, c, sweep.cells[c].offset))
                        addCandidates(cellValues(rule, c, sweep.cells[c].offset), candidates);
    // The level that decides the most cells of near sweeps' rules; the lowest on a tie.
    std::optional<OccupancyLevel> best;
    size_t bestCells = 0;
    for (const auto& [value, strict] : candidates) {
        const OccupancyLevel level{value, strict};
        size_t cells = 0;
        for (const ir::IrGrammar& grammar : module.grammars)
            for (const IrSweep& sweep : grammar.sweeps) {
                if (!nearCells(sweep)) continue;
                for (const IrRule& rule : sweep.rules)
                    for (uint32_t c = 0; c < sweep.cells.size(); ++c)
                        cells += levelSide(rule, c, sweep.cells[c].offset, level) != LevelSide::Any ? 1 : 0;
            }
        if (cells > bestCells) {
            best = level;
            bestCells = cells;
        }
    }
    return best;
}

std::string occupancyLevelGlsl(const std::optional<OccupancyLevel>& level) {
    if (!level)
        return "// None: no rule cell of a sweep that tiles can skip tests a level.\n"
               "const bool OCCUPANCY_LEVEL = false;\n"
               "bool occupied(float density) { return false; }\n";
    return fmt::format("const bool OCCUPANCY_LEVEL = true;\n"
                       "bool occupied(float density) {{ return density {} {}; }}\n",
                       level->strict ? ">" : ">=", glslFloat(level->value));
}

std::string activeTilesKernelSource(const ir::IrGrammar& grammar, const IrSweep& sweep, std::string_view kernelName,
                                     std::string_view sourceName, const std::optional<OccupancyLevel>& level) {
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
         {"OCCUPANCY_LEVEL", occupancyLevelGlsl(level)},
         {"MAY_MATCH", mayMatch(sweep, level)}});
}

DispatchShape tileRangesDispatchShape() { return DispatchShape{{8, 1, 1}, {1, 1, 1}}; }

std::string tileRangesKernelSource(const std::optional<OccupancyLevel>& level) {
    return instantiateTemplate("tile_ranges.glsl", {{"OCCUPANCY_LEVEL", occupancyLevelGlsl(level)}});
}

} // namespace voxc::codegen
