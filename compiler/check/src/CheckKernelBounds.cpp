#include "CheckKernelBounds.h"

#include "voxc/program/PointSet.h"
#include "voxc/program/Semantics.h"

#include <algorithm>
#include <glm/common.hpp>
#include <fmt/format.h>
#include <map>
#include <utility>

namespace voxc::check {

namespace {

// The loop iterations of a field's point-set lookups (its other code is straight-line, or loops a
// fixed number of times that the driver unrolls).
uint64_t fieldLoopIterations(const Field& field) {
    uint64_t iterations = 0;
    for (const FieldNode& node : field.nodes)
        if (node.kind == FieldNode::Kind::PointSet && node.pointSet) iterations += pointSetLookupIterations(node.pointSet->bins);
    return iterations;
}

// Perlin's permutation is written into each invocation's private table at the top of main, one
// store per entry (noise_permutation.glsl's initializer); counted as that many loop iterations.
constexpr uint64_t kNoiseTableIterations = 256;

// One sweep's stamp kernel (stamp.glsl): its stamps' field code and the loop iterations of one
// voxel's invocation. The code holds one block per group of rules whose stamps differ only by
// their symmetry variant, i.e. per declared stamp (a variant repeats its rule's stamps, same
// place); every block runs for every firing, masked, as the lanes of a group fired different rules.
void checkStampKernel(Context& context, const Grammar& grammar, const CheckedGrammar& syntax, const Sweep& sweep,
                      const std::vector<Field>& fields) {
    struct Declared {
        uint32_t rule, stamp;
    };
    std::map<std::pair<int32_t, int32_t>, Declared> declared; // by the stamp block's place
    glm::ivec3 reach(0);
    for (uint32_t r : sweep.rules)
        for (uint32_t s = 0; s < grammar.rules[r].stamps.size(); ++s) {
            const Stamp& stamp = grammar.rules[r].stamps[s];
            declared.try_emplace({stamp.loc.line, stamp.loc.column}, Declared{r, s});
            reach = glm::max(reach, stamp.reach);
        }
    if (declared.empty()) return;

    uint64_t nodes = 0, perFiring = 0, costliest = 0;
    Declared costliestStamp = declared.begin()->second;
    for (const auto& [place, d] : declared) {
        const Stamp& stamp = grammar.rules[d.rule].stamps[d.stamp];
        if (stamp.field >= fields.size()) return; // an unknown field, reported already
        const Field& field = fields[stamp.field];
        nodes += field.nodes.size();
        if (nodes > uint64_t(context.limits.maxKernelFieldNodes)) {
            context.diagnostics.error(
                "E0012", stamp.loc,
                fmt::format("the stamp kernel of grammar '{}' (window [{}, {}, {}]) holds {} field nodes with this stamp "
                            "of '{}' ({} nodes), more than the limit of {} one kernel may hold; fewer or smaller "
                            "stamped fields, or rules of another window size (a kernel of their own), fit",
                            grammar.name, sweep.window.x, sweep.window.y, sweep.window.z, nodes, stamp.fieldName,
                            field.nodes.size(), context.limits.maxKernelFieldNodes));
            return;
        }
        const uint64_t loops = fieldLoopIterations(field);
        perFiring += loops;
        if (loops > costliest) costliest = loops, costliestStamp = d;
    }

    // The phase's anchors whose windows, grown by the sweep's reach, hold one voxel, per axis.
    glm::i64vec3 covering;
    for (int axis = 0; axis < 3; ++axis) {
        const int64_t spacing = int64_t(sweep.phaseCount[axis]) * grammar.stride[axis];
        const int64_t grown = int64_t(sweep.window[axis]) + 2 * int64_t(reach[axis]);
        const int64_t anchors = (int64_t(sweep.anchorCount[axis]) + sweep.phaseCount[axis] - 1) / sweep.phaseCount[axis];
        covering[axis] = std::max<int64_t>(std::min((grown + spacing - 1) / spacing, anchors), 1);
    }
    // stamp.glsl's loops: z, y, the words of the row's firing bits, the set bits of a word; each
    // loop also counts the test that leaves it.
    const uint64_t z = uint64_t(covering.z), y = uint64_t(covering.y);
    const uint64_t words = (uint64_t(covering.x) + 30) / 32 + 1, bitsPerWord = std::min<uint64_t>(uint64_t(covering.x), 32);
    const uint64_t firings = z * y * words * bitsPerWord;
    const uint64_t iterations =
        kNoiseTableIterations + (z + 1) + z * (y + 1) + z * y * (words + 1) + z * y * words * (bitsPerWord + 1) + firings * perFiring;
    if (iterations <= uint64_t(context.limits.maxKernelLoopIterations)) return;
    const Rule& rule = grammar.rules[costliestStamp.rule];
    const Stamp& stamp = rule.stamps[costliestStamp.stamp];
    context.diagnostics.error(
        "E0012", syntax.rules.at(costliestStamp.rule).stampReachLocs.at(costliestStamp.stamp),
        fmt::format("rule '{}': the stamp pass of grammar '{}' (window [{}, {}, {}]) may loop {} times for one voxel ({} "
                    "firings can cover it, each stamp of the sweep walking its carve's lists: {} iterations a firing, "
                    "{} of them for '{}'), more than the limit of {} a kernel may loop; a smaller reach, a larger "
                    "grammar stride or a sparser lsystem_cave (longer steps, a larger spacing) fits",
                    rule.name, grammar.name, sweep.window.x, sweep.window.y, sweep.window.z, iterations, firings,
                    perFiring, costliest, stamp.fieldName, context.limits.maxKernelLoopIterations));
}

} // namespace

uint64_t speleothemLoopIterations(const SpeleothemStage& stage, int32_t height) {
    // speleothem_grow.glsl, per source column (four for a hoodoo): the air-mask words, the rock
    // voxels bottom up (plus one test per word), then per closed run up to gap/2 + 1 steps of
    // the feature, each with its taper loop (taper + 1) and at most height writes in all, each
    // write a keep_clear lookup; and the permutation table simplex3 reads, stored at the top.
    const uint64_t sources = stage.params.kind == SpeleothemKind::Hoodoo ? 4 : 1;
    const uint64_t h = uint64_t(std::max(height, 0)), words = (h + 31) / 32 + 1;
    const uint64_t lookup = stage.clearance ? pointSetLookupIterations(stage.clearance->bins) : 0;
    return kNoiseTableIterations + sources * (2 * words + h + h * (uint64_t(stage.params.taper) + 2) + h * lookup);
}

void checkKernelBounds(Context& context, const Program& program, const std::vector<CheckedGrammar>& syntax) {
    for (size_t g = 0; g < program.grammars.size() && g < syntax.size(); ++g) {
        // Once per grammar: a rule's variants of other window sizes would repeat the error.
        const int errorsBefore = context.diagnostics.errorCount();
        for (const Sweep& sweep : orderSweeps(program.grammars[g]))
            if (context.diagnostics.errorCount() == errorsBefore)
                checkStampKernel(context, program.grammars[g], syntax[g], sweep, program.fields);
    }
    for (const SpeleothemStage& stage : program.speleothems) {
        if (!stage.clearance) continue; // without keep_clear, at most 256 + 4 * (2 * 17 + 512 * 11) at the grid's limit
        const uint64_t iterations = speleothemLoopIterations(stage, program.world.size.y);
        if (iterations <= uint64_t(context.limits.maxKernelLoopIterations)) continue;
        context.diagnostics.error(
            "E0012", stage.loc,
            fmt::format("speleothems '{}': a column of its grow kernel may loop {} times ({} voxels high, each voxel it "
                        "grows tested against keep_clear's lists: {} iterations a test), more than the limit of {} a "
                        "kernel may loop; a sparser carve (longer steps, a larger spacing), a lower grid or no "
                        "keep_clear fits",
                        stage.name, iterations, program.world.size.y, pointSetLookupIterations(stage.clearance->bins),
                        context.limits.maxKernelLoopIterations));
    }
}

} // namespace voxc::check
