#pragma once
// Counter-based draws and the two selection rules (docs/architecture.md, "Selection"). Every random
// decision of the L-system is a pure hash of its key, never a stateful generator, so any part of
// an expansion can be recomputed alone and the result never depends on evaluation order.
#include "voxc/generators/lsystem/Definition.h"

#include <cstdint>
#include <span>

namespace voxc::lsystem {

// Independent families of draws.
enum class Stream : uint32_t {
    Production = 1,   // which production rewrites a symbol
    Macro = 2,        // which substitute replaces a macro occurrence
    Jitter = 3,       // angle deviation of one turn
    ConnectShuffle = 4,
    ConnectChance = 5,
    RandomRule = 6,
    Crossover = 7,
    Mutation = 8,
    Generation = 9,
};

// (seed, stream, step, position, occurrence): e.g. expansion k, index of the rewritten symbol in
// the string before the pass, index of the macro occurrence in the production's right side.
struct DrawKey {
    uint32_t seed = 0;
    Stream stream = Stream::Production;
    uint32_t step = 0;
    uint32_t position = 0;
    uint32_t occurrence = 0;
};

inline constexpr uint32_t kNoCandidate = 0xffffffffu;

// Uniform in [0, 1) with 53 random bits; `candidate` separates per-candidate draws of one key.
double uniform(const DrawKey& key, uint32_t candidate = kNoCandidate);

// A uniform integer in [0, count) (count >= 1).
uint32_t uniformIndex(const DrawKey& key, uint32_t count, uint32_t candidate = kNoCandidate);

// Chooses one of weights.size() >= 1 alternatives; offsets (same size, or empty for none) are
// the modes' adjustments: added to the score under `thesis`, applied as a factor exp(offset)
// under `weighted`. A single alternative draws nothing.
size_t choose(Selection rule, std::span<const double> weights, std::span<const double> offsets, const DrawKey& key);

} // namespace voxc::lsystem
