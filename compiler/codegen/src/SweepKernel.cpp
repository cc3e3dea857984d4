#include "KernelSources.h"
#include "Template.h"

#include "voxc/builtins/Ops.h"
#include "voxc/core/Errors.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

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
uint32_t maskCount(const IrCell& cell) { return uint32_t(cell.tests.size() + kBitsPerMask - 1) / kBitsPerMask; }
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
    std::string t = "// The live rules of this sweep in declaration order:\n";
    std::vector<std::string> priorities, weights, probabilities;
    for (uint32_t r = 0; r < sweep.rules.size(); ++r) {
        const IrRule& rule = sweep.rules[r];
        t += fmt::format("//   {}: {} (rule {} of grammar {}, {})\n", r, rule.name, rule.ruleIndex, g.name,
                         where(src, rule.loc));
        priorities.push_back(fmt::format("{}", rule.priority));
        weights.push_back(fmt::format("{}u", rule.weightUnits));
        probabilities.push_back(fmt::format("{}u", rule.probabilityUnits));
    }
    t += fmt::format("const int RULE_COUNT = {};\n", sweep.rules.size());
    t += fmt::format("const int RULE_PRIORITY[RULE_COUNT] = int[]({});\n", fmt::join(priorities, ", "));
    t += fmt::format("const uint RULE_WEIGHT_UNITS[RULE_COUNT] = uint[]({});\n", fmt::join(weights, ", "));
    t += fmt::format("const uint RULE_PROBABILITY_UNITS[RULE_COUNT] = uint[]({});\n", fmt::join(probabilities, ", "));
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

std::string loadWindow(const IrSweep& sweep) {
    const glm::ivec3 w = sweep.window;
    std::string s = fmt::format("// Window {}: cell i sits at anchor + (i % {}, i / {} % {}, i / {}).\n", printVec(w),
                                w.x, w.x, w.y, w.x * w.y);
    std::vector<uint32_t> unused;
    for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
        const IrCell& cell = sweep.cells[c];
        if (cell.access == CellAccess::None) {
            unused.push_back(c);
            continue;
        }
        s += fmt::format("int address{} = voxelAddress(anchor + ivec3({}, {}, {}));\n", c, cell.offset.x, cell.offset.y,
                         cell.offset.z);
        if (cell.access == CellAccess::Load) s += fmt::format("float cell{0} = voxels.density[address{0}];\n", c);
    }
    if (!unused.empty())
        s += fmt::format("// No live rule reads or writes cell{} {}.\n", unused.size() == 1 ? "" : "s", fmt::join(unused, ", "));
    return s;
}

std::string passMasks(const IrSweep& sweep) {
    std::string s;
    for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
        const IrCell& cell = sweep.cells[c];
        if (cell.tests.empty()) continue;
        VOXC_ASSERT(cell.access == CellAccess::Load);
        if (s.empty())
            s = "// Each distinct predicate of a cell is evaluated once, into one bit of the cell's pass mask.\n";
        for (uint32_t word = 0; word < maskCount(cell); ++word) {
            const std::string name = maskName(cell, c, word);
            const uint32_t first = word * kBitsPerMask;
            const uint32_t last = std::min<uint32_t>(first + kBitsPerMask, uint32_t(cell.tests.size()));
            for (uint32_t b = first; b < last; ++b) {
                const Predicate& p = cell.tests[b];
                const std::string test = symbolOpInfo(p.op).glsl(fmt::format("cell{}", c), glslFloat(p.value));
                const std::string lead =
                    b == first ? fmt::format("uint {} = ", name) : std::string(name.size() + 6, ' ');
                s += fmt::format("{}{}({} ? 0x{:x}u : 0u){} // bit {}: {}\n", lead, b == first ? "" : "| ", test,
                                 1u << (b - first), b + 1 == last ? ";" : "", b - first, printPredicate(p));
            }
        }
    }
    return s.empty() ? s : s + "\n";
}

std::string matchRules(const IrSweep& sweep, std::string_view src) {
    std::string s = "// A rule matches when every cell has all the bits the rule needs.\nbool matched[RULE_COUNT];\n";
    for (uint32_t r = 0; r < sweep.rules.size(); ++r) {
        const IrRule& rule = sweep.rules[r];
        VOXC_ASSERT(rule.needs.size() == sweep.cells.size());
        s += symbolComment(sweep, rule, fmt::format("{}: {} ({})", r, rule.name, where(src, rule.loc)));
        std::vector<std::string> tests;
        for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
            std::vector<uint32_t> words(maskCount(sweep.cells[c]), 0u);
            for (uint32_t bit : rule.needs[c])
                words[bit / kBitsPerMask] |= 1u << (bit % kBitsPerMask);
            for (uint32_t word = 0; word < words.size(); ++word)
                if (words[word] != 0)
                    tests.push_back(fmt::format("({} & 0x{:x}u) == 0x{:x}u", maskName(sweep.cells[c], c, word),
                                                words[word], words[word]));
        }
        const std::string lead = fmt::format("matched[{}] = ", r);
        if (tests.empty()) s += lead + "true;\n";
        for (size_t i = 0; i < tests.size(); ++i)
            s += fmt::format("{}{}{}\n", i == 0 ? lead : std::string(lead.size() - 3, ' ') + "&& ", tests[i],
                             i + 1 == tests.size() ? ";" : "");
    }
    return s;
}

std::string applyRule(const IrGrammar& g, const IrSweep& sweep, std::string_view src) {
    const bool clamps = g.clampMin || g.clampMax;
    std::string s = "// Apply the chosen rule's transform; NOP cells are left untouched";
    s += clamps ? " and every written value is clamped.\n" : ".\n";
    for (uint32_t r = 0; r < sweep.rules.size(); ++r) {
        const IrRule& rule = sweep.rules[r];
        s += fmt::format("{}if (chosen == {}) {{ // {} ({})\n", r == 0 ? "" : "} else ", r, rule.name,
                         where(src, rule.loc));
        bool writes = false;
        for (uint32_t c = 0; c < sweep.cells.size(); ++c) {
            const TransformCell& t = rule.transform[c];
            const TransformOpInfo& info = transformOpInfo(t.op);
            if (!info.writes) continue;
            VOXC_ASSERT(sweep.cells[c].access != CellAccess::None);
            writes = true;
            // `precise` keeps the value exactly what the interpreter's float arithmetic gives.
            s += fmt::format("    precise float next{} = {}; // {} {}\n", c,
                             info.glsl(fmt::format("cell{}", c), glslFloat(t.value)), printCell(sweep.cells[c].offset),
                             printTransform(t));
            s += fmt::format("    voxels.density[address{0}] = {1}next{0}{2};\n", c, clamps ? "clampDensity(" : "",
                             clamps ? ")" : "");
        }
        if (!writes) s += "    // every cell NOP: the window stays as it is\n";
    }
    if (!sweep.rules.empty()) s += "}\n";
    return s;
}

} // namespace

std::string sweepKernelSource(const IrGrammar& grammar, const IrSweep& sweep, std::string_view kernelName,
                              std::string_view sourceName) {
    const std::string headerComment = header(grammar, sweep, kernelName, sourceName);
    if (sweep.rules.empty()) return instantiateTemplate("noop_sweep.glsl", {{"HEADER", headerComment}});
    return instantiateTemplate("sweep.glsl", {{"HEADER", headerComment},
                                              {"RULE_TABLE", ruleTable(grammar, sweep, sourceName)},
                                              {"LOAD_WINDOW", loadWindow(sweep)},
                                              {"PASS_MASKS", passMasks(sweep)},
                                              {"MATCH_RULES", matchRules(sweep, sourceName)},
                                              {"APPLY_RULE", applyRule(grammar, sweep, sourceName)}});
}

} // namespace voxc::codegen
