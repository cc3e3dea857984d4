#include "GrammarCone.h"

#include "voxc/program/Semantics.h"

#include <algorithm>
#include <cstdint>
#include <fmt/format.h>
#include <glm/common.hpp>
#include <numeric>
#include <vector>

namespace voxc::stages {

namespace {

// Positions tried per axis at most; a longer period (phase counts with a huge lcm) falls back to
// the bound of every phase moving a cone end by its whole window.
constexpr int64_t kMaxPeriod = 4096;

int64_t floorDiv(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

int64_t ceilDiv(int64_t a, int64_t b) { return -floorDiv(-a, b); }

// One phase along one axis: windows of `window` cells start at residue * stride + k * period;
// a window's stamps write `reach` cells beyond it on each side, and what they write depends on
// the whole window (whether its rule fired) and on the voxel itself.
struct AxisPhase {
    int64_t window, stride, period, residue, reach;

    // The lowest cell x depends on after the phase: the first cell of the lowest window whose
    // grown box holds x, or x itself.
    int64_t startHolding(int64_t x) const {
        const int64_t base = residue * stride;
        const int64_t start = base + ceilDiv(x - window - reach + 1 - base, period) * period;
        return start <= x + reach ? std::min(x, start) : x;
    }
    // The highest: the last cell of the highest window whose grown box holds x, or x itself.
    int64_t endHolding(int64_t x) const {
        const int64_t base = residue * stride;
        const int64_t start = base + floorDiv(x + reach - base, period) * period;
        return start > x - window - reach ? std::max(x, start + window - 1) : x;
    }
};

// How far each end of one position's cone moves in one iteration: `down[p]` for the low end at
// position p (mod period), `up[p]` for the high end.
struct IterationMoves {
    int64_t period = 1;
    std::vector<int64_t> down, up;
};

IterationMoves iterationMoves(const std::vector<AxisPhase>& phases, int64_t period) {
    IterationMoves moves;
    if (period > kMaxPeriod) {
        // Every phase may move an end by its window and reach less one cell.
        int64_t most = 0;
        for (const AxisPhase& phase : phases) most += phase.window + phase.reach - 1;
        moves.down = moves.up = {most};
        return moves;
    }
    moves.period = period;
    for (int64_t p = 0; p < period; ++p) {
        int64_t lo = p, hi = p;
        for (auto it = phases.rbegin(); it != phases.rend(); ++it) lo = it->startHolding(lo), hi = it->endHolding(hi);
        moves.down.push_back(p - lo);
        moves.up.push_back(hi - p);
    }
    return moves;
}

// The farthest an end moves over `iterations`, from any start position, capped at `cap`.
int64_t farthest(const std::vector<int64_t>& move, int64_t period, int64_t iterations, int64_t cap, int sign) {
    int64_t most = 0;
    for (int64_t start = 0; start < period && most < cap; ++start) {
        int64_t at = start;
        for (int64_t i = 0; i < iterations; ++i) {
            const int64_t step = move[size_t(((at % period) + period) % period)];
            if (step == 0) break; // a fixed point: every later iteration leaves it there
            at += sign * step;
            if (sign * (at - start) >= cap) break;
        }
        most = std::max(most, std::min(cap, sign * (at - start)));
    }
    return most;
}

} // namespace

glm::ivec3 grammarConeRadius(const Grammar& grammar, glm::ivec3 cap) {
    const std::vector<Sweep> sweeps = orderSweeps(grammar);
    glm::ivec3 radius(0);
    for (int axis = 0; axis < 3; ++axis) {
        const int64_t stride = grammar.stride[axis];
        std::vector<AxisPhase> phases;
        int64_t lcm = 1;
        for (const Sweep& sweep : sweeps) {
            // A sweep whose window never fits the bounds has no anchor.
            if (sweep.anchorCount.x == 0 || sweep.anchorCount.y == 0 || sweep.anchorCount.z == 0) continue;
            const int64_t m = sweep.phaseCount[axis];
            lcm = std::min(std::lcm(lcm, m), kMaxPeriod + 1);
            int64_t reach = 0;
            for (uint32_t r : sweep.rules)
                for (const Stamp& stamp : grammar.rules[r].stamps) reach = std::max<int64_t>(reach, stamp.reach[axis]);
            for (int p = 0; p < sweep.phases(); ++p)
                phases.push_back({sweep.window[axis], stride, m * stride, phaseResidue(sweep, p)[axis], reach});
        }
        if (phases.empty() || cap[axis] <= 0) continue;
        const IterationMoves moves = iterationMoves(phases, std::min(lcm * stride, kMaxPeriod + 1));
        const int64_t down = farthest(moves.down, int64_t(moves.down.size()), grammar.iterations, cap[axis], -1);
        const int64_t up = farthest(moves.up, int64_t(moves.up.size()), grammar.iterations, cap[axis], 1);
        radius[axis] = int32_t(std::max(down, up));
    }
    return radius;
}

std::string describeSweeps(const Grammar& grammar) {
    std::string text;
    for (const Sweep& sweep : orderSweeps(grammar)) {
        text += fmt::format("{}[{}, {}, {}] in {} phase{}", text.empty() ? "sweeps " : ", ", sweep.window.x,
                            sweep.window.y, sweep.window.z, sweep.phases(), sweep.phases() == 1 ? "" : "s");
        glm::ivec3 reach(0);
        bool stamps = false;
        for (uint32_t r : sweep.rules)
            for (const Stamp& stamp : grammar.rules[r].stamps) {
                reach = glm::max(reach, stamp.reach);
                stamps = true;
            }
        if (stamps) text += fmt::format(" with stamps reaching [{}, {}, {}]", reach.x, reach.y, reach.z);
    }
    return text + fmt::format(" at stride [{}, {}, {}]", grammar.stride.x, grammar.stride.y, grammar.stride.z);
}

} // namespace voxc::stages
