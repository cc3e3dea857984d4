#include "voxc/codegen/KernelSources.h"
#include "voxc/codegen/Template.h"

#include "voxc/builtins/Ops.h"
#include "voxc/core/Errors.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>

namespace voxc::codegen {

namespace {

using ir::CellAccess;
using ir::IrCell;
using ir::IrGrammar;
using ir::IrRule;
using ir::IrSweep;
using ir::printCell;
using ir::printPredicate;
using ir::printTransform;
using ir::printVec;

std::string where(std::string_view sourceName, const SourceLoc& loc) {
    return fmt::format("{}:{}:{}", sourceName, loc.line, loc.column);
}

// One 32-bit pass mask per 32 distinct tests of a cell.
constexpr uint32_t kBitsPerMask = 32;
uint32_t maskCount(const IrCell& cell) { return (ir::testCount(cell) + kBitsPerMask - 1) / kBitsPerMask; }
std::string maskName(const IrCell& cell, uint32_t c, uint32_t word) {
    return maskCount(cell) == 1 ? fmt::format("pass{}", c) : fmt::format("pass{}_{}", c, word);
}

// The rule's symbol as comment lines, non-IGN cells only, wrapped to stay readable.
std::string symbolComment(const IrSweep& sweep, const IrRule& rule, const std::string& title) {
    constexpr size_t kWidth = 100;
    std::vector<std::string> parts;
    for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
        std::vector<std::string> predicates;
        for (const Predicate& p : rule.symbol[c].predicates)
            if (p.op != SymbolOp::IGN) predicates.push_back(printPredicate(p));
        for (const MaterialPredicate& p : rule.symbol[c].materialPredicates)
            predicates.push_back(ir::printMaterialPredicate(p));
        if (!predicates.empty())
            parts.push_back(fmt::format("{} {}", printCell(sweep.cells[c].offset), fmt::join(predicates, " & ")));
    }
    if (parts.empty()) return "// " + title + ": every cell IGN\n";
    std::string out = "// " + title + ":";
    size_t lineStart = 0;
    for (size_t i = 0; i < parts.size(); ++i) {
        if (i > 0 && out.size() - lineStart + parts[i].size() + 3 > kWidth) {
            out += " |\n//   ";
            lineStart = out.size() - 5;
        } else if (i > 0) {
            out += " |";
        }
        out += " " + parts[i];
    }
    return out + "\n";
}

std::string header(const IrGrammar& g, const IrSweep& sweep, std::string_view kernelName, std::string_view src) {
    std::string h =
        fmt::format("voxc generated kernel \"{}\" from {} grammar {}.\n", kernelName, where(src, g.loc), g.name);
    h += fmt::format("Sweep {} runs every rule of window {}: {} anchors in {} phases.\n", sweep.index,
                     printVec(sweep.window), printVec(sweep.anchorCount), printVec(sweep.phaseCount));
    h += fmt::format("Grammar stride {}, bounds {}..{}, {} iteration(s)", printVec(g.stride), printVec(g.boundsMin),
                     printVec(g.boundsMax), g.iterations);
    if (g.clampMin || g.clampMax)
        h += fmt::format(", clamp [{}, {}]", g.clampMin ? glslFloat(*g.clampMin) : "-",
                         g.clampMax ? glslFloat(*g.clampMax) : "-");
    h += ".\nRules (declaration order):\n";
    for (const IrRule& rule : sweep.rules)
        h += fmt::format("  {} ({}): priority {}, weight {} units, probability {} / 2^24\n", rule.name,
                         where(src, rule.loc), rule.priority, rule.weightUnits, rule.probabilityUnits);
    for (const ir::IrRemovedRule& removed : sweep.removed)
        h += fmt::format("  {} ({}): removed, cell {} passes no density so it never matches\n", removed.name,
                         where(src, removed.loc), printCell(sweep.cells[removed.cell].offset));
    return prefixLines(h, "// ");
}

std::string ruleTable(const IrGrammar& g, const IrSweep& sweep, std::string_view src) {
    std::string t = "// The live rules of this sweep in declaration order (matchedN, weightN below):\n";
    for (uint32_t r = 0; r < sweep.rules.size(); ++r) {
        const IrRule& rule = sweep.rules[r];
        t += fmt::format("//   {}: {} (rule {} of grammar {}, {})\n", r, rule.name, rule.ruleIndex, g.name,
                         where(src, rule.loc));
    }
    if (g.clampMin || g.clampMax) {
        // The same comparisons as std::max(v, min) then std::min(v, max) in voxc::applyTransform.
        t += "\n// The grammar's clamp, applied to every written value as the CPU does it.\n";
        t += "float clampDensity(float v) {\n";
        if (g.clampMin) t += fmt::format("    v = v < {0} ? {0} : v;\n", glslFloat(*g.clampMin));
        if (g.clampMax) t += fmt::format("    v = {0} < v ? {0} : v;\n", glslFloat(*g.clampMax));
        t += "    return v;\n}\n";
    }
    return t;
}

// Cells with tests, in the order the kernel reads them: those more rules test first and, among
// them, those with fewer distinct predicates (more selective), so a window that matches nothing
// is usually rejected after its first reads.
std::vector<uint32_t> testOrder(const IrSweep& sweep) {
    std::vector<uint32_t> order, users(sweep.cells.size(), 0);
    for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
        for (const IrRule& rule : sweep.rules) users[c] += rule.needs[c].empty() ? 0 : 1;
        if (ir::testCount(sweep.cells[c]) != 0) order.push_back(c);
    }
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        if (users[a] != users[b]) return users[a] > users[b];
        return ir::testCount(sweep.cells[a]) < ir::testCount(sweep.cells[b]);
    });
    return order;
}

// Bit `bit` of cell c's pass mask as a GLSL bool expression, and the test it is.
std::pair<std::string, std::string> cellTest(const IrCell& cell, uint32_t c, uint32_t bit) {
    if (bit < cell.tests.size()) {
        const Predicate& p = cell.tests[bit];
        return {symbolOpInfo(p.op).glsl(fmt::format("cell{}", c), glslFloat(p.value)), printPredicate(p)};
    }
    const MaterialPredicate& p = cell.materialTests[bit - cell.tests.size()];
    return {materialOpInfo(p.op).glsl(fmt::format("material{}", c), fmt::format("{}u", p.material)),
            ir::printMaterialPredicate(p)};
}

std::string cellAddress(const IrCell& cell) {
    return fmt::format("windowCellAddress(window, ivec3({}, {}, {}))", cell.offset.x, cell.offset.y, cell.offset.z);
}

// A rule's `where` tests, once its cells matched: voxc::aggregatePasses written out cell by
// cell, in the same order and with the same float operations (Aggregates.h).
std::string aggregateTests(const IrRule& rule, uint32_t r) {
    std::string body;
    for (const AggregateTest& test : rule.aggregates) {
        const auto density = [](glm::ivec3 c) {
            return fmt::format("voxels.density[windowCellAddress(window, ivec3({}, {}, {}))]", c.x, c.y, c.z);
        };
        std::string lines;
        switch (test.kind) {
        case AggregateKind::Mean:
            lines = "float sum = 0.0;\n";
            forEachAggregateCell(test, [&](glm::ivec3 c) { lines += fmt::format("sum = sum + {};\n", density(c)); });
            lines += fmt::format("matched{} = sum >= {} && sum <= {};\n", r, glslFloat(test.low), glslFloat(test.high));
            break;
        case AggregateKind::Min:
        case AggregateKind::Max: {
            const char* keep = test.kind == AggregateKind::Min ? "d < m" : "m < d";
            lines = fmt::format("float m = {};\nfloat d;\n", density(test.boxMin));
            forEachAggregateCell(test, [&](glm::ivec3 c) {
                lines += fmt::format("d = {};\nm = {} ? d : m;\n", density(c), keep);
            });
            lines += fmt::format("matched{} = m >= {} && m <= {};\n", r, glslFloat(test.low), glslFloat(test.high));
            break;
        }
        case AggregateKind::SolidFraction:
        case AggregateKind::MaterialFraction:
            lines = "uint count = 0u;\n";
            forEachAggregateCell(test, [&](glm::ivec3 c) {
                lines += test.kind == AggregateKind::SolidFraction
                             ? fmt::format("count += {} >= {} ? 1u : 0u;\n", density(c), glslFloat(kSolidDensity))
                             : fmt::format("count += materials.material[windowCellAddress(window, ivec3({}, {}, {}))] "
                                           "== {}u ? 1u : 0u;\n",
                                           c.x, c.y, c.z, test.material);
            });
            lines += fmt::format("matched{} = count >= {}u && count <= {}u;\n", r, test.minCount, test.maxCount);
            break;
        }
        body += fmt::format("if (matched{}) {{ // {}\n{}}}\n", r, ir::printAggregate(test), prefixLines(lines, "    "));
    }
    return fmt::format("\n// Rule {}'s aggregate tests, once its cells matched.\n", r) + body;
}

// Reads the window's tested cells one at a time, each only while a rule that tests it can still
// match, and narrows `matchedN` (rule N matches while every cell read so far has all the bits
// it needs). The order changes which cells are read, never which rules match.
std::string matchWindow(const IrSweep& sweep, std::string_view src) {
    const glm::ivec3 w = sweep.window;
    std::string s = fmt::format("// Window {}: cell i sits at anchor + (i % {}, i / {} % {}, i / {}).\n", printVec(w), w.x,
                                w.x, w.y, w.x * w.y);
    s += fmt::format("WindowAddressing window = windowAddressing(anchor, ivec3({}, {}, {}));\n", w.x, w.y, w.z);
    std::vector<uint32_t> used, unused;
    for (uint32_t c = 0; c < sweep.cells.size(); ++c)
        (sweep.cells[c].access == CellAccess::None ? unused : used).push_back(c);
    for (uint32_t c : used) {
        s += fmt::format("int address{0} = 0;\nfloat cell{0} = 0.0;\n", c);
        if (sweep.cells[c].loadsMaterial) s += fmt::format("uint material{} = 0u;\n", c);
    }
    if (!unused.empty())
        s += fmt::format("// No live rule reads or writes cell{} {}.\n", unused.size() == 1 ? "" : "s",
                         fmt::join(unused, ", "));

    s += "\n// The rules' symbols; a rule matches when every cell has all the bits the rule needs.\n";
    for (uint32_t r = 0; r < sweep.rules.size(); ++r) {
        const IrRule& rule = sweep.rules[r];
        VOXC_ASSERT(rule.needs.size() == sweep.cells.size());
        s += symbolComment(sweep, rule, fmt::format("{}: {} ({})", r, rule.name, where(src, rule.loc)));
        s += fmt::format("bool matched{} = true;\n", r);
    }

    bool firstCell = true;
    for (uint32_t c : testOrder(sweep)) {
        const IrCell& cell = sweep.cells[c];
        VOXC_ASSERT(cell.access != CellAccess::None);
        std::vector<std::string> testers;
        for (uint32_t r = 0; r < sweep.rules.size(); ++r)
            if (!sweep.rules[r].needs[c].empty()) testers.push_back(fmt::format("matched{}", r));
        s += fmt::format("\n// Cell {} {}: each distinct predicate is one bit of its pass mask.\n", c,
                         printCell(cell.offset));
        std::string body = fmt::format("address{} = {};\n", c, cellAddress(cell));
        if (cell.access == CellAccess::Load) body += fmt::format("cell{0} = voxels.density[address{0}];\n", c);
        if (cell.loadsMaterial) body += fmt::format("material{0} = materials.material[address{0}];\n", c);
        for (uint32_t word = 0; word < maskCount(cell); ++word) {
            const std::string name = maskName(cell, c, word);
            const uint32_t first = word * kBitsPerMask;
            const uint32_t last = std::min<uint32_t>(first + kBitsPerMask, ir::testCount(cell));
            for (uint32_t b = first; b < last; ++b) {
                const auto [test, what] = cellTest(cell, c, b);
                const std::string lead =
                    b == first ? fmt::format("uint {} = ", name) : std::string(name.size() + 6, ' ') + "| ";
                body += fmt::format("{}({} ? 0x{:x}u : 0u){} // bit {}: {}\n", lead, test, 1u << (b - first),
                                    b + 1 == last ? ";" : "", b - first, what);
            }
        }
        for (uint32_t r = 0; r < sweep.rules.size(); ++r) {
            std::vector<uint32_t> words(maskCount(cell), 0u);
            for (uint32_t bit : sweep.rules[r].needs[c]) words[bit / kBitsPerMask] |= 1u << (bit % kBitsPerMask);
            for (uint32_t word = 0; word < words.size(); ++word)
                if (words[word] != 0)
                    body += fmt::format("matched{0} = matched{0} && ({1} & 0x{2:x}u) == 0x{2:x}u;\n", r,
                                        maskName(cell, c, word), words[word]);
        }
        if (firstCell) {
            s += body;
        } else {
            s += fmt::format("if ({}) {{\n{}}}\n", fmt::join(testers, " || "), prefixLines(body, "    "));
        }
        firstCell = false;
    }
    for (uint32_t r = 0; r < sweep.rules.size(); ++r)
        if (!sweep.rules[r].aggregates.empty()) s += aggregateTests(sweep.rules[r], r);
    return s;
}

// voxc::chooseRule unrolled over the rule table: every rule a scalar, no arrays (drivers that
// keep arrays in memory, such as llvmpipe, pay for each indexed access).
std::string chooseRule(const IrSweep& sweep) {
    const uint32_t n = uint32_t(sweep.rules.size());
    std::string s = "// voxc::chooseRule: the highest priority among the matched rules wins; equal priorities are\n"
                    "// drawn by weight in declaration order; the chosen rule then fires with its probability.\n";
    for (uint32_t r = 0; r < n; ++r)
        s += fmt::format("uint weight{0} = matched{0} ? {1}u : 0u;\n", r, sweep.rules[r].weightUnits);

    // Priority levels, highest first; a matched rule of a level silences every lower level.
    std::map<int32_t, std::vector<uint32_t>, std::greater<>> levels;
    for (uint32_t r = 0; r < n; ++r) levels[sweep.rules[r].priority].push_back(r);
    if (levels.size() > 1) {
        s += "// Only the highest matched priority competes: a level with a match silences the lower ones.\n";
        std::vector<uint32_t> lower;
        for (const auto& [priority, rules] : levels) lower.insert(lower.end(), rules.begin(), rules.end());
        bool firstLevel = true;
        for (auto level = levels.begin(); std::next(level) != levels.end(); ++level) {
            lower.erase(lower.begin(), lower.begin() + ptrdiff_t(level->second.size()));
            std::vector<std::string> sum, silence;
            for (uint32_t r : level->second) sum.push_back(fmt::format("weight{}", r));
            for (uint32_t r : lower) silence.push_back(fmt::format("weight{} = 0u;", r));
            s += fmt::format("{}if ({} != 0u) {{ // priority {}\n    {}\n", firstLevel ? "" : "} else ",
                             fmt::join(sum, " + "), level->first, fmt::join(silence, " "));
            firstLevel = false;
        }
        s += "}\n";
    }

    std::vector<std::string> all;
    for (uint32_t r = 0; r < n; ++r) all.push_back(fmt::format("weight{}", r));
    s += fmt::format("uint total = {};\nint chosen = -1;\nif (total != 0u) {{\n", fmt::join(all, " + "));
    s += "    uint target = ruleChoiceDraw(anchorWorld) % total;\n";
    s += "    // The first rule whose running weight sum exceeds the target, in declaration order.\n";
    s += "    uint upTo = weight0;\n    chosen = target < upTo ? 0 : -1;\n";
    for (uint32_t r = 1; r < n; ++r)
        s += fmt::format("    upTo += weight{0};\n    if (chosen < 0 && target < upTo) chosen = {0};\n", r);
    bool certain = true;
    for (const IrRule& rule : sweep.rules) certain = certain && rule.probabilityUnits >= kProbabilityOne;
    if (certain) {
        s += "    // Every rule has probability 1: the draw (< 2^24) always passes, so it is skipped.\n";
    } else {
        s += "    uint probability = ";
        for (uint32_t r = 0; r + 1 < n; ++r)
            s += fmt::format("chosen == {} ? {}u : ", r, sweep.rules[r].probabilityUnits);
        s += fmt::format("{}u;\n", sweep.rules[n - 1].probabilityUnits);
        s += "    if (probabilityDraw(anchorWorld) >= probability) chosen = -1;\n";
    }
    return s + "}\n";
}

std::string applyRule(const IrGrammar& g, const IrSweep& sweep, std::string_view src) {
    const bool clamps = g.clampMin || g.clampMax;
    std::string s = "// Apply the chosen rule's transform; NOP cells are left untouched";
    s += clamps ? ", every written value is clamped" : "";
    s += " and a non-finite one is stored as 0.\n";
    for (uint32_t r = 0; r < sweep.rules.size(); ++r) {
        const IrRule& rule = sweep.rules[r];
        s += fmt::format("{}if (chosen == {}) {{ // {} ({})\n", r == 0 ? "" : "} else ", r, rule.name,
                         where(src, rule.loc));
        bool writes = false;
        for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
            const TransformCell& t = rule.transform[c];
            const TransformOpInfo& info = transformOpInfo(t.op);
            if (!info.writes && !t.material) continue;
            VOXC_ASSERT(sweep.cells[c].access != CellAccess::None);
            writes = true;
            // matchWindow read only the cells this rule tests; fetch the others it transforms.
            if (rule.needs[c].empty()) {
                s += fmt::format("    address{} = {};\n", c, cellAddress(sweep.cells[c]));
                if (info.writes && sweep.cells[c].access == CellAccess::Load)
                    s += fmt::format("    cell{0} = voxels.density[address{0}];\n", c);
            }
            if (info.writes) {
                // `precise` keeps the value exactly what the interpreter's float arithmetic gives.
                // A zero amount is kept from the compilers (as opaque_constants.glsl does): they
                // would fold d + 0 into d, keeping a -0 that the interpreter's addition makes +0.
                const std::string amount = t.value == 0.0f
                                               ? fmt::format("(gl_NumWorkGroups.x == 0u ? 1.0 : {})", glslFloat(t.value))
                                               : glslFloat(t.value);
                s += fmt::format("    precise float next{} = {}; // {} {}\n", c, info.glsl(fmt::format("cell{}", c), amount),
                                 printCell(sweep.cells[c].offset), printTransform(t));
                // A value that is not finite (an ADD past the float range) is stored as 0 and counted.
                const glm::ivec3 o = sweep.cells[c].offset;
                s += fmt::format("    writeDensity(address{0}, finiteDensity({1}next{0}{2}, anchor + ivec3({3}, {4}, {5})));\n",
                                 c, clamps ? "clampDensity(" : "", clamps ? ")" : "", o.x, o.y, o.z);
            }
            // After the density, unclamped; tile ranges track densities only, so nothing else.
            if (t.material)
                s += fmt::format("    materials.material[address{}] = {}u; // {} {}\n", c, *t.material,
                                 printCell(sweep.cells[c].offset), printTransform(t));
        }
        if (!writes) s += "    // every cell NOP: the window stays as it is\n";
    }
    if (!sweep.rules.empty()) s += "}\n";
    return s;
}

} // namespace

DispatchShape sweepDispatchShape(const IrSweep&) {
    // A workgroup of 8 x 8 anchors in x and y, one anchor per invocation (see sweep.glsl); an
    // indirect dispatch numbers a chunk's anchors by the local index instead.
    return DispatchShape{{8, 8, 1}, {1, 1, 1}};
}

std::string sweepKernelSource(const IrGrammar& grammar, const IrSweep& sweep, std::string_view kernelName,
                              std::string_view sourceName, const std::optional<OccupancyLevel>& level) {
    const std::string headerComment = header(grammar, sweep, kernelName, sourceName);
    const std::string shape = dispatchShapeGlsl(sweepDispatchShape(sweep));
    if (sweep.rules.empty())
        return instantiateTemplate("noop_sweep.glsl", {{"HEADER", headerComment}, {"DISPATCH_SHAPE", shape}});
    // A sweep with stamps records every anchor's choice for its stamp pass (StampKernel.cpp).
    const bool stamps = sweepHasStamps(sweep);
    std::string rules = ruleTable(grammar, sweep, sourceName);
    std::string apply = applyRule(grammar, sweep, sourceName);
    if (stamps) {
        rules += "\n" + firedRecordGlsl(grammar, sweep);
        apply += "firedRule.rule[firedIndex(anchor)] = uint(chosen + 1);\n" + firingBitGlsl(sweep);
    }
    return instantiateTemplate("sweep.glsl", {{"HEADER", headerComment},
                                              {"DISPATCH_SHAPE", shape},
                                              {"RULE_TABLE", rules},
                                              {"MATCH_WINDOW", matchWindow(sweep, sourceName)},
                                              {"CHOOSE_RULE", chooseRule(sweep)},
                                              {"APPLY_RULE", apply},
                                              {"OCCUPANCY_LEVEL", occupancyLevelGlsl(level)}});
}

} // namespace voxc::codegen
