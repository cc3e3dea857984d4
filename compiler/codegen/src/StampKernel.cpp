// The stamp pass of a sweep whose rules stamp fields (stamp.glsl), and the record of fired rules
// the sweep kernel leaves for it in kBindingScratch.
#include "voxc/codegen/KernelSources.h"
#include "voxc/codegen/Template.h"

#include "voxc/builtins/Ops.h"
#include "voxc/ir/Ir.h"

#include <fmt/format.h>
#include <glm/common.hpp>

#include <algorithm>
#include <vector>

namespace voxc::codegen {

namespace {

std::string ivec3Glsl(glm::ivec3 v) { return fmt::format("ivec3({}, {}, {})", v.x, v.y, v.z); }

// The written rule's reach of a stamp (Stamp::reach is per variant axis: written[from[axis]]).
glm::ivec3 writtenReach(const Stamp& stamp) {
    glm::ivec3 written(0);
    for (int axis = 0; axis < 3; ++axis) written[stamp.from[axis]] = stamp.reach[axis];
    return written;
}

// Whether two rules' stamps are the same stamps seen through different symmetry variants (each
// rule's stamps share its variant's from and negate, Symmetry.cpp): then one block of code serves
// both, the variant read from the tables at run time, so a kernel does not grow with the variants.
bool sameStampsUpToVariant(const std::vector<Stamp>& a, const std::vector<Stamp>& b) {
    const auto same = [](const Stamp& x, const Stamp& y) {
        return x.field == y.field && x.fieldName == y.fieldName && x.loc.line == y.loc.line &&
               x.loc.column == y.loc.column && x.mode == y.mode && x.material == y.material &&
               glm::all(glm::equal(x.offset, y.offset)) && x.writtenSize == y.writtenSize &&
               writtenReach(x) == writtenReach(y);
    };
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), same);
}

std::string stampGlsl(const ir::IrModule& module, const Stamp& stamp, std::string_view sourceName,
                      std::vector<std::string_view>& libraries) {
    const StampFieldCode field = stampFieldGlsl(module, module.fields.at(stamp.field), sourceName);
    // Libraries in the order the fields need them (a library includes after those it calls).
    for (std::string_view library : field.libraries)
        if (std::find(libraries.begin(), libraries.end(), library) == libraries.end()) libraries.push_back(library);
    std::string body = fmt::format("ivec3 written = stampWrittenCell(fromAnchor, variantFrom, variantNegate, {});\n",
                                   ivec3Glsl(stamp.writtenSize));
    body += fmt::format("precise vec3 stampPosition = vec3(written) - vec3({}, {}, {});\n", glslFloat(stamp.offset.x),
                        glslFloat(stamp.offset.y), glslFloat(stamp.offset.z));
    body += field.statements;
    body += fmt::format("float fieldValue = finiteDensity({}, local);\n", field.value);
    body += combineFieldGlsl(stamp.mode, stamp.material, "fieldValue");
    return fmt::format("// stamp {} {} ({}:{}:{}), written reach {}\n"
                       "reach = stampVariantReach({}, variantFrom);\n"
                       "if (all(greaterThanEqual(fromAnchor, -reach)) && all(lessThan(fromAnchor, WINDOW + reach))) {{\n{}}}\n",
                       ir::fieldModeName(stamp.mode), stamp.fieldName, sourceName, stamp.loc.line, stamp.loc.column,
                       ir::printVec(writtenReach(stamp)), ivec3Glsl(writtenReach(stamp)), prefixLines(body, "    "));
}

} // namespace

bool sweepHasStamps(const ir::IrSweep& sweep) {
    return std::any_of(sweep.rules.begin(), sweep.rules.end(), [](const ir::IrRule& r) { return !r.stamps.empty(); });
}

namespace {

// Anchors of one phase along each axis, at most: ceil(anchorCount / phaseCount).
glm::ivec3 phaseAnchors(const ir::IrSweep& sweep) { return (sweep.anchorCount + sweep.phaseCount - 1) / sweep.phaseCount; }

uint64_t anchorWords(const ir::IrSweep& sweep) {
    return uint64_t(sweep.anchorCount.x) * uint64_t(sweep.anchorCount.y) * uint64_t(sweep.anchorCount.z);
}

// One bit per anchor of a phase, rows along x of whole words.
uint64_t firingBitWords(const ir::IrSweep& sweep) {
    const glm::ivec3 anchors = phaseAnchors(sweep);
    return uint64_t((anchors.x + 31) / 32) * uint64_t(anchors.y) * uint64_t(anchors.z);
}

} // namespace

uint64_t sweepFiredWords(const ir::IrSweep& sweep) { return anchorWords(sweep) + firingBitWords(sweep); }

glm::ivec3 sweepStampReach(const ir::IrSweep& sweep) {
    glm::ivec3 reach(0);
    for (const ir::IrRule& rule : sweep.rules)
        for (const Stamp& stamp : rule.stamps) reach = glm::max(reach, stamp.reach);
    return reach;
}

std::string firedRecordGlsl(const ir::IrGrammar& grammar, const ir::IrSweep& sweep) {
    const glm::ivec3 anchors = phaseAnchors(sweep);
    return fmt::format(
        "// The rule each anchor of the sweep fired (1 + its index among the live rules, 0: none), at the\n"
        "// anchor's number n = (anchor - bounds min) / stride, x fastest (kBindingScratch).\n"
        "layout(std430, set = 0, binding = 11) buffer FiredRule {{\n    uint rule[];\n}} firedRule;\n\n"
        "ivec3 anchorNumber(ivec3 anchor) {{ return (anchor - {}) / {}; }}\n\n"
        "int firedIndex(ivec3 anchor) {{\n    ivec3 n = anchorNumber(anchor);\n    return n.x + {} * (n.y + {} * n.z);\n}}\n\n"
        "// After the rules, the current phase's firing bits: bit m.x of row (m.y, m.z) is set where the\n"
        "// anchor m = n / phaseCount of the phase fired a rule with stamps, so the stamp pass visits\n"
        "// those anchors alone, in anchor order. The sweep kernel sets or clears every bit of its phase.\n"
        "const ivec3 PHASE_COUNT = {};\nconst int FIRING_ROW_WORDS = {};\n\n"
        "ivec3 phaseLattice(ivec3 anchor) {{ return anchorNumber(anchor) / PHASE_COUNT; }}\n\n"
        "int firingRow(ivec3 m) {{ return {} + FIRING_ROW_WORDS * (m.y + {} * m.z); }}\n",
        ivec3Glsl(grammar.boundsMin), ivec3Glsl(grammar.stride), sweep.anchorCount.x, sweep.anchorCount.y,
        ivec3Glsl(sweep.phaseCount), (anchors.x + 31) / 32, anchorWords(sweep), anchors.y);
}

std::string firingBitGlsl(const ir::IrSweep& sweep) {
    std::vector<std::string> stamping;
    for (uint32_t r = 0; r < sweep.rules.size(); ++r)
        if (!sweep.rules[r].stamps.empty()) stamping.push_back(fmt::format("chosen == {}", r));
    return fmt::format("{{ // this anchor's firing bit (stamp pass)\n"
                       "    ivec3 m = phaseLattice(anchor);\n"
                       "    int word = firingRow(m) + (m.x >> 5);\n"
                       "    uint bit = 1u << uint(m.x & 31);\n"
                       "    if ({}) atomicOr(firedRule.rule[word], bit);\n"
                       "    else atomicAnd(firedRule.rule[word], ~bit);\n}}\n",
                       fmt::join(stamping, " || "));
}

DispatchShape stampDispatchShape() { return DispatchShape{{8, 8, 1}, {1, 1, 1}}; }

std::string stampKernelSource(const ir::IrModule& module, const ir::IrGrammar& grammar, const ir::IrSweep& sweep,
                              std::string_view kernelName, std::string_view sourceName) {
    std::string header = fmt::format("voxc generated kernel \"{}\": the stamps of grammar {} ({}:{}:{}), sweep {} "
                                     "(window {}).\n",
                                     kernelName, grammar.name, sourceName, grammar.loc.line, grammar.loc.column,
                                     sweep.index, ir::printVec(sweep.window));
    std::vector<std::string_view> libraries;
    // Stamping rules in groups of symmetry variants (first rule of each group first), and per
    // live rule its group and variant axes, the tables the stamp code reads at run time.
    std::vector<std::vector<uint32_t>> groups;
    std::vector<int> groupOf(sweep.rules.size(), -1);
    for (uint32_t r = 0; r < sweep.rules.size(); ++r) {
        const ir::IrRule& rule = sweep.rules[r];
        if (rule.stamps.empty()) continue;
        for (size_t g = 0; g < groups.size() && groupOf[r] < 0; ++g)
            if (sameStampsUpToVariant(sweep.rules[groups[g].front()].stamps, rule.stamps)) groupOf[r] = int(g);
        if (groupOf[r] < 0) {
            groupOf[r] = int(groups.size());
            groups.emplace_back();
        }
        groups[size_t(groupOf[r])].push_back(r);
    }
    std::vector<std::string> groupEntries, fromEntries, negateEntries;
    for (uint32_t r = 0; r < sweep.rules.size(); ++r) {
        const ir::IrRule& rule = sweep.rules[r];
        const Stamp identity;
        const Stamp& axes = rule.stamps.empty() ? identity : rule.stamps.front();
        groupEntries.push_back(std::to_string(groupOf[r]));
        fromEntries.push_back(ivec3Glsl(axes.from));
        negateEntries.push_back(fmt::format("bvec3({}, {}, {})", axes.negate.x, axes.negate.y, axes.negate.z));
    }
    const std::string tables = fmt::format(
        "\n// Per live rule (fired - 1): its group of stamps (-1: none) and its variant's axes (Stamp::from,\n"
        "// Stamp::negate), read at run time so that symmetry variants share their stamps' code.\n"
        "const int STAMP_GROUP[{0}] = int[]({1});\nconst ivec3 STAMP_FROM[{0}] = ivec3[]({2});\n"
        "const bvec3 STAMP_NEGATE[{0}] = bvec3[]({3});\n",
        sweep.rules.size(), fmt::join(groupEntries, ", "), fmt::join(fromEntries, ", "),
        fmt::join(negateEntries, ", "));
    std::string blocks;
    for (size_t g = 0; g < groups.size(); ++g) {
        std::vector<std::string> names;
        for (uint32_t r : groups[g])
            names.push_back(fmt::format("{} ({}:{}:{})", sweep.rules[r].name, sourceName, sweep.rules[r].loc.line,
                                        sweep.rules[r].loc.column));
        std::string body;
        for (const Stamp& stamp : sweep.rules[groups[g].front()].stamps)
            body += stampGlsl(module, stamp, sourceName, libraries);
        blocks += fmt::format("if (group == {}) {{ // {}\n{}}}\n", g, fmt::join(names, ", "), prefixLines(body, "    "));
    }
    const std::string stamps = fmt::format("int group = STAMP_GROUP[fired - 1u];\nivec3 variantFrom = STAMP_FROM[fired - 1u];\n"
                          "bvec3 variantNegate = STAMP_NEGATE[fired - 1u];\nivec3 reach;\n{}",
                          blocks);
    std::string includes;
    for (std::string_view library : libraries) includes += fmt::format("#include \"{}\"\n", library);
    if (includes.empty()) includes = "// No function library needed.\n";
    const glm::ivec3 last = grammar.boundsMin + (sweep.anchorCount - 1) * grammar.stride;
    const std::string constants =
        firedRecordGlsl(grammar, sweep) +
        fmt::format("\nconst ivec3 WINDOW = {};\nconst ivec3 REACH = {};\nconst ivec3 PHASE_STEP = {};\n"
                    "const ivec3 LAST_ANCHOR = {};\n",
                    ivec3Glsl(sweep.window), ivec3Glsl(sweepStampReach(sweep)),
                    ivec3Glsl(sweep.phaseCount * grammar.stride), ivec3Glsl(last)) +
        tables;
    return instantiateTemplate("stamp.glsl", {{"HEADER", prefixLines(header, "// ")},
                                              {"LIBRARIES", includes},
                                              {"DISPATCH_SHAPE", dispatchShapeGlsl(stampDispatchShape())},
                                              {"SWEEP_CONSTANTS", constants},
                                              {"STAMPS", stamps}});
}

} // namespace voxc::codegen
