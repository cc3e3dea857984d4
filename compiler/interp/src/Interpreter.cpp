#include "voxc/interp/Interpreter.h"

#include "voxc/builtins/Ops.h"
#include "voxc/builtins/Shapes.h"
#include "voxc/core/Errors.h"
#include "voxc/interp/FieldEval.h"
#include "voxc/program/Semantics.h"

#include <algorithm>
#include <glm/common.hpp>
#include <cstddef>
#include <memory>
#include <vector>

namespace voxc {

namespace {

// What one sweep needs at every anchor, computed once per grammar run.
struct PreparedSweep {
    const Sweep* sweep = nullptr;
    std::vector<ptrdiff_t> cellOffsets;  // grid-index offset of each window cell from the anchor, cellIndex order
    std::vector<PhaseAnchors> phases;
};

PreparedSweep prepareSweep(const Grammar& grammar, const Sweep& sweep, const DenseGrid& grid) {
    PreparedSweep prepared;
    prepared.sweep = &sweep;
    const glm::ivec3 w = sweep.window;
    prepared.cellOffsets.resize(size_t(w.x) * w.y * w.z);
    for (int z = 0; z < w.z; ++z)
        for (int y = 0; y < w.y; ++y)
            for (int x = 0; x < w.x; ++x)
                prepared.cellOffsets[size_t(cellIndex(w, x, y, z))] = ptrdiff_t(grid.index({x, y, z}));
    for (int p = 0; p < sweep.phases(); ++p) prepared.phases.push_back(phaseAnchors(grammar, sweep, p));
    return prepared;
}

// A window in the grid's two channels: the anchor's density and material; cells at offsets.
struct WindowView {
    float* density = nullptr;
    uint8_t* material = nullptr;
};

bool windowMatches(const Rule& rule, WindowView anchor, const std::vector<ptrdiff_t>& offsets) {
    for (size_t c = 0; c < offsets.size(); ++c)
        if (!cellPasses(rule.symbol[c], anchor.density[offsets[c]], anchor.material[offsets[c]])) return false;
    const auto offset = [&](glm::ivec3 cell) { return offsets[size_t(cellIndex(rule.size, cell.x, cell.y, cell.z))]; };
    for (const AggregateTest& test : rule.aggregates)
        if (!aggregatePasses(
                test, [&](glm::ivec3 cell) { return anchor.density[offset(cell)]; },
                [&](glm::ivec3 cell) { return anchor.material[offset(cell)]; }))
            return false;
    return true;
}

// `anchorIndex`: the anchor's grid index, for counting non-finite writes.
void applyRule(const Rule& rule, const Grammar& grammar, WindowView anchor, size_t anchorIndex,
               const std::vector<ptrdiff_t>& offsets, NonFiniteCount& nonFinite) {
    for (size_t c = 0; c < offsets.size(); ++c) {
        const TransformCell& transform = rule.transform[c];
        float& cell = anchor.density[offsets[c]];
        cell = nonFinite.replace(applyTransform(transform, cell, grammar), uint64_t(ptrdiff_t(anchorIndex) + offsets[c]));
        if (transform.material) anchor.material[offsets[c]] = *transform.material;
    }
}

// The stamps of one phase (Semantics.h): after every window of the phase was matched and
// transformed, each firing's stamps in anchor order (z, then y, then x), each over its window
// grown by its reach and clipped to the grid, combined as voxc::combineField does. So a voxel's
// result is the same whichever device or chunk size folds the stamps covering it.
struct StampFiring {
    glm::ivec3 anchor;
    const Rule* rule;
};

void applyStamps(const Program& program, glm::ivec3 window, const std::vector<StampFiring>& firings, DenseGrid& grid,
                 std::vector<std::unique_ptr<FieldEvaluator>>& evaluators, NonFiniteCount& nonFinite) {
    for (const StampFiring& firing : firings)
        for (const Stamp& stamp : firing.rule->stamps) {
            std::unique_ptr<FieldEvaluator>& evaluator = evaluators.at(stamp.field);
            if (!evaluator)
                evaluator = std::make_unique<FieldEvaluator>(program.fields[stamp.field], program.world.origin);
            const uint32_t root = program.fields[stamp.field].root;
            const glm::ivec3 lo = glm::max(firing.anchor - stamp.reach, glm::ivec3(0));
            const glm::ivec3 hi = glm::min(firing.anchor + window + stamp.reach, grid.size());
            for (int z = lo.z; z < hi.z; ++z)
                for (int y = lo.y; y < hi.y; ++y)
                    for (int x = lo.x; x < hi.x; ++x) {
                        const glm::ivec3 v(x, y, z);
                        const float value =
                            evaluator->evaluateAt(stampLocal(stamp, v - firing.anchor), program.world.origin + v)[root].v.x;
                        const float f = nonFinite.replace(value, grid.index(v));
                        const VoxelState voxel =
                            combineField(stamp.mode, stamp.material, f, {grid.at(v), grid.materialAt(v)});
                        grid.at(v) = voxel.density;
                        grid.materialAt(v) = voxel.material;
                    }
        }
}

void checkFits(const Grammar& grammar, const DenseGrid& grid) {
    const glm::ivec3 size = grid.size();
    for (int axis = 0; axis < 3; ++axis) {
        VOXC_ASSERT(grammar.boundsMin[axis] >= 0 && grammar.boundsMax[axis] <= size[axis]);
        VOXC_ASSERT(grammar.stride[axis] >= 1);
    }
    for (const Rule& rule : grammar.rules) {
        const size_t cells = size_t(rule.size.x) * rule.size.y * rule.size.z;
        VOXC_ASSERT(rule.symbol.size() == cells && rule.transform.size() == cells);
    }
}

} // namespace

DenseGrid evaluateStart(const Program& program) {
    DenseGrid grid(program.world.size); // air: what a start without shapes leaves
    if (program.start.empty()) return grid;
    const glm::ivec3 size = program.world.size;
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const VoxelState voxel = startVoxel(program, {x, y, z});
                grid.at({x, y, z}) = voxel.density;
                grid.materialAt({x, y, z}) = voxel.material;
            }
    return grid;
}

void runGrammar(const Program& program, uint32_t grammarIndex, DenseGrid& grid, const InterpOptions& options,
                NonFiniteCount* nonFinite) {
    VOXC_ASSERT(grammarIndex < program.grammars.size());
    VOXC_ASSERT(grid.size() == program.world.size);
    const Grammar& grammar = program.grammars[grammarIndex];
    checkFits(grammar, grid);

    const std::vector<Sweep> sweeps = orderSweeps(grammar);
    std::vector<PreparedSweep> prepared;
    size_t maxRules = 0;
    for (const Sweep& sweep : sweeps) {
        prepared.push_back(prepareSweep(grammar, sweep, grid));
        maxRules = std::max(maxRules, sweep.rules.size());
    }
    if (options.stats) {
        options.stats->firings.resize(program.grammars.size());
        options.stats->anchors.resize(program.grammars.size(), 0);
        options.stats->firings[grammarIndex].resize(grammar.rules.size(), 0);
    }

    std::vector<uint32_t> matched;
    matched.reserve(maxRules);
    std::vector<StampFiring> stampFirings;
    std::vector<std::unique_ptr<FieldEvaluator>> stampEvaluators(program.fields.size());
    float* data = grid.data().data();
    uint8_t* materials = grid.materials().data();
    const uint32_t seed = program.world.seed;
    const glm::ivec3 origin = program.world.origin;
    NonFiniteCount uncounted;
    NonFiniteCount& replaced = nonFinite ? *nonFinite : uncounted;

    for (uint32_t iteration = 0; iteration < uint32_t(grammar.iterations); ++iteration) {
        if (options.progress) options.progress(double(iteration) / double(grammar.iterations));
        for (uint32_t s = 0; s < prepared.size(); ++s) {
            const PreparedSweep& sweep = prepared[s];
            for (uint32_t phase = 0; phase < sweep.phases.size(); ++phase) {
                const PhaseAnchors& anchors = sweep.phases[phase];
                stampFirings.clear();
                if (options.stats)
                    options.stats->anchors[grammarIndex] +=
                        uint64_t(anchors.count.x) * uint64_t(anchors.count.y) * uint64_t(anchors.count.z);
                for (int k = 0; k < anchors.count.z; ++k) {
                    for (int j = 0; j < anchors.count.y; ++j) {
                        for (int i = 0; i < anchors.count.x; ++i) {
                            const glm::ivec3 anchor = anchors.start + glm::ivec3(i, j, k) * anchors.step;
                            const size_t index = grid.index(anchor);
                            const WindowView base{data + index, materials + index};
                            matched.clear();
                            for (uint32_t r : sweep.sweep->rules)
                                if (windowMatches(grammar.rules[r], base, sweep.cellOffsets)) matched.push_back(r);
                            if (matched.empty()) continue;
                            const int chosen = chooseRule(grammar, matched, seed, iteration, s, anchor + origin);
                            if (chosen < 0) continue;
                            // Windows of one phase never overlap, so writing in place is safe.
                            const Rule& rule = grammar.rules[size_t(chosen)];
                            applyRule(rule, grammar, base, index, sweep.cellOffsets, replaced);
                            if (!rule.stamps.empty()) stampFirings.push_back({anchor, &rule});
                            if (options.stats) ++options.stats->firings[grammarIndex][size_t(chosen)];
                            if (options.onFire)
                                options.onFire(TraceEvent{grammarIndex, iteration, s, phase, anchor, uint32_t(chosen)});
                        }
                    }
                }
                applyStamps(program, sweep.sweep->window, stampFirings, grid, stampEvaluators, replaced);
            }
        }
    }
}

} // namespace voxc
