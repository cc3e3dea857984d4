#include "voxc/generators/lsystem/Selection.h"

#include "voxc/program/Random.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace voxc::lsystem {

namespace {

uint32_t hashKey(const DrawKey& key, uint32_t candidate, uint32_t word) {
    uint32_t h = mix32(uint32_t(key.stream) ^ (word * 0x9E3779B9u));
    h = mix32(candidate ^ h);
    h = mix32(key.occurrence ^ h);
    h = mix32(key.position ^ h);
    h = mix32(key.step ^ h);
    return mix32(key.seed ^ h);
}

double offsetAt(std::span<const double> offsets, size_t i) { return offsets.empty() ? 0.0 : offsets[i]; }

} // namespace

double uniform(const DrawKey& key, uint32_t candidate) {
    const uint64_t high = hashKey(key, candidate, 0) >> 5; // 27 bits
    const uint64_t low = hashKey(key, candidate, 1) >> 6;  // 26 bits
    return double((high << 26) | low) * 0x1p-53;
}

uint32_t uniformIndex(const DrawKey& key, uint32_t count, uint32_t candidate) {
    VOXC_ASSERT(count >= 1);
    return std::min(count - 1, uint32_t(uniform(key, candidate) * count));
}

size_t choose(Selection rule, std::span<const double> weights, std::span<const double> offsets, const DrawKey& key) {
    VOXC_ASSERT(!weights.empty() && (offsets.empty() || offsets.size() == weights.size()));
    if (weights.size() == 1) return 0;
    if (rule == Selection::Thesis) {
        size_t best = 0;
        double bestScore = -std::numeric_limits<double>::infinity();
        for (size_t i = 0; i < weights.size(); ++i) {
            const double score = uniform(key, uint32_t(i)) + weights[i] + offsetAt(offsets, i);
            if (score > bestScore) best = i, bestScore = score;
        }
        return best;
    }
    // Weighted: max(w, 0) * exp(offset). Offsets are shifted by their largest value among the
    // candidates that can win, which leaves the probabilities unchanged and keeps exp finite
    // however far the balanced mode's running offset has drifted.
    double shift = -std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < weights.size(); ++i)
        if (weights[i] > 0) shift = std::max(shift, offsetAt(offsets, i));
    if (shift == -std::numeric_limits<double>::infinity()) {
        // No positive weight: the largest adjusted weight, the lowest index on ties.
        size_t best = 0;
        for (size_t i = 1; i < weights.size(); ++i)
            if (weights[i] + offsetAt(offsets, i) > weights[best] + offsetAt(offsets, best)) best = i;
        return best;
    }
    double total = 0;
    for (size_t i = 0; i < weights.size(); ++i)
        if (weights[i] > 0) total += weights[i] * std::exp(offsetAt(offsets, i) - shift);
    const double target = uniform(key) * total;
    double running = 0;
    size_t last = 0;
    for (size_t i = 0; i < weights.size(); ++i) {
        if (!(weights[i] > 0)) continue;
        running += weights[i] * std::exp(offsetAt(offsets, i) - shift);
        last = i;
        if (target < running) return i;
    }
    return last; // rounding left target at the very top
}

} // namespace voxc::lsystem
