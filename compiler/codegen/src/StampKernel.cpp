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

// Where voxc::stampLocal reads each written axis from: `fromAnchor`'s axes, mirrored or not.
std::string writtenCellGlsl(const Stamp& stamp) {
    std::string parts[3];
    for (int axis = 0; axis < 3; ++axis) {
        const int from = stamp.from[axis];
        parts[from] = stamp.negate[axis] ? fmt::format("{} - fromAnchor.{}", stamp.writtenSize[from] - 1, "xyz"[axis])
                                         : fmt::format("fromAnchor.{}", "xyz"[axis]);
    }
    return fmt::format("ivec3({}, {}, {})", parts[0], parts[1], parts[2]);
}

std::string stampGlsl(const ir::IrModule& module, const ir::IrSweep& sweep, const Stamp& stamp,
                      std::string_view sourceName, std::vector<std::string_view>& libraries) {
    const StampFieldCode field = stampFieldGlsl(module, module.fields.at(stamp.field), sourceName);
    // Libraries in the order the fields need them (a library includes after those it calls).
    for (std::string_view library : field.libraries)
        if (std::find(libraries.begin(), libraries.end(), library) == libraries.end()) libraries.push_back(library);
    std::string body = fmt::format("ivec3 written = {};\n", writtenCellGlsl(stamp));
    body += fmt::format("precise vec3 stampPosition = vec3(written) - vec3({}, {}, {});\n", glslFloat(stamp.offset.x),
                        glslFloat(stamp.offset.y), glslFloat(stamp.offset.z));
    body += field.statements;
    body += fmt::format("float fieldValue = finiteDensity({}, local);\n", field.value);
    body += combineFieldGlsl(stamp.mode, stamp.material, "fieldValue");
    return fmt::format("// stamp {} {} ({}:{}:{}), reach {}\n"
                       "if (all(greaterThanEqual(fromAnchor, -{})) && all(lessThan(fromAnchor, {}))) {{\n{}}}\n",
                       ir::fieldModeName(stamp.mode), stamp.fieldName, sourceName, stamp.loc.line, stamp.loc.column,
                       ir::printVec(stamp.reach), ivec3Glsl(stamp.reach), ivec3Glsl(sweep.window + stamp.reach),
                       prefixLines(body, "    "));
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
    std::string stamps;
    for (uint32_t r = 0; r < sweep.rules.size(); ++r) {
        const ir::IrRule& rule = sweep.rules[r];
        if (rule.stamps.empty()) continue;
        std::string body;
        for (const Stamp& stamp : rule.stamps) body += stampGlsl(module, sweep, stamp, sourceName, libraries);
        stamps += fmt::format("if (fired == {}u) {{ // {} ({}:{}:{})\n{}}}\n", r + 1, rule.name, sourceName,
                              rule.loc.line, rule.loc.column, prefixLines(body, "    "));
    }
    std::string includes;
    for (std::string_view library : libraries) includes += fmt::format("#include \"{}\"\n", library);
    if (includes.empty()) includes = "// No function library needed.\n";
    const glm::ivec3 last = grammar.boundsMin + (sweep.anchorCount - 1) * grammar.stride;
    const std::string constants =
        firedRecordGlsl(grammar, sweep) +
        fmt::format("\nconst ivec3 WINDOW = {};\nconst ivec3 REACH = {};\nconst ivec3 PHASE_STEP = {};\n"
                    "const ivec3 LAST_ANCHOR = {};\n",
                    ivec3Glsl(sweep.window), ivec3Glsl(sweepStampReach(sweep)),
                    ivec3Glsl(sweep.phaseCount * grammar.stride), ivec3Glsl(last));
    return instantiateTemplate("stamp.glsl", {{"HEADER", prefixLines(header, "// ")},
                                              {"LIBRARIES", includes},
                                              {"DISPATCH_SHAPE", dispatchShapeGlsl(stampDispatchShape())},
                                              {"SWEEP_CONSTANTS", constants},
                                              {"STAMPS", stamps}});
}

} // namespace voxc::codegen
