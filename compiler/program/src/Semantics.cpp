#include "voxc/program/Semantics.h"

#include "voxc/program/Random.h"

#include <algorithm>

namespace voxc {

std::vector<Sweep> orderSweeps(const Grammar& grammar) {
    std::vector<Sweep> sweeps;
    for (uint32_t i = 0; i < grammar.rules.size(); ++i) {
        const glm::ivec3 size = grammar.rules[i].size;
        auto it = std::find_if(sweeps.begin(), sweeps.end(), [&](const Sweep& s) { return s.window == size; });
        if (it == sweeps.end()) {
            Sweep sweep;
            sweep.window = size;
            sweeps.push_back(sweep);
            it = sweeps.end() - 1;
        }
        it->rules.push_back(i);
    }
    // stable_sort keeps declaration order among equal volumes.
    std::stable_sort(sweeps.begin(), sweeps.end(), [](const Sweep& a, const Sweep& b) {
        return a.window.x * a.window.y * a.window.z > b.window.x * b.window.y * b.window.z;
    });
    for (Sweep& sweep : sweeps) {
        for (int axis = 0; axis < 3; ++axis) {
            const int span = grammar.boundsMax[axis] - grammar.boundsMin[axis] - sweep.window[axis];
            sweep.anchorCount[axis] = span < 0 ? 0 : span / grammar.stride[axis] + 1;
            sweep.phaseCount[axis] = (sweep.window[axis] + grammar.stride[axis] - 1) / grammar.stride[axis];
        }
    }
    return sweeps;
}

glm::ivec3 phaseResidue(const Sweep& sweep, int phase) {
    const glm::ivec3 m = sweep.phaseCount;
    return {phase % m.x, (phase / m.x) % m.y, phase / (m.x * m.y)};
}

PhaseAnchors phaseAnchors(const Grammar& grammar, const Sweep& sweep, int phase) {
    const glm::ivec3 residue = phaseResidue(sweep, phase);
    PhaseAnchors anchors;
    for (int axis = 0; axis < 3; ++axis) {
        const int n = sweep.anchorCount[axis];
        const int m = sweep.phaseCount[axis];
        // The first anchor here whose declared number is residue mod m.
        const int first = ((residue[axis] - grammar.firstAnchor[axis]) % m + m) % m;
        anchors.start[axis] = grammar.boundsMin[axis] + first * grammar.stride[axis];
        anchors.step[axis] = m * grammar.stride[axis];
        anchors.count[axis] = first < n ? (n - first + m - 1) / m : 0;
    }
    return anchors;
}

int chooseRule(const Grammar& grammar, const std::vector<uint32_t>& matched, uint32_t seed, uint32_t iteration,
               uint32_t sweepIndex, glm::ivec3 anchorWorld) {
    if (matched.empty()) return -1;
    int32_t best = grammar.rules[matched.front()].priority;
    for (uint32_t r : matched) best = std::max(best, grammar.rules[r].priority);
    uint32_t total = 0;
    for (uint32_t r : matched)
        if (grammar.rules[r].priority == best) total += grammar.rules[r].weightUnits;
    const uint32_t target = anchorHash(seed, iteration, sweepIndex, anchorWorld, RandomStream::RuleChoice) % total;
    uint32_t accumulated = 0;
    int chosen = -1;
    for (uint32_t r : matched) {
        if (grammar.rules[r].priority != best) continue;
        accumulated += grammar.rules[r].weightUnits;
        if (target < accumulated) {
            chosen = int(r);
            break;
        }
    }
    const uint32_t draw = anchorHash(seed, iteration, sweepIndex, anchorWorld, RandomStream::Probability) >> 8;
    return draw < grammar.rules[chosen].probabilityUnits ? chosen : -1;
}

} // namespace voxc

namespace voxc {

void combineFieldRow(FieldMode mode, std::optional<uint8_t> material, const float* f, int n, float* d, uint8_t* m) {
    // One loop per mode with the mode's test inlined, so the compiler can vectorise it.
    const auto each = [&](auto combine) {
        for (int i = 0; i < n; ++i) {
            const VoxelState out = combine(f[i], VoxelState{d[i], m[i]});
            d[i] = out.density;
            m[i] = out.material;
        }
    };
    switch (mode) {
    case FieldMode::Set: return each([&](float v, VoxelState s) { return combineField(FieldMode::Set, material, v, s); });
    case FieldMode::Union: return each([&](float v, VoxelState s) { return combineField(FieldMode::Union, material, v, s); });
    case FieldMode::Subtract:
        return each([&](float v, VoxelState s) { return combineField(FieldMode::Subtract, material, v, s); });
    case FieldMode::Intersect:
        return each([&](float v, VoxelState s) { return combineField(FieldMode::Intersect, material, v, s); });
    case FieldMode::Paint: return each([&](float v, VoxelState s) { return combineField(FieldMode::Paint, material, v, s); });
    }
}

} // namespace voxc
