#pragma once
// Counter-based randomness (digest §1, decision 4): every random choice is a pure hash of
// (seed, iteration, sweep, anchor, stream). compiler/shaders/random.glsl mirrors
// this function exactly; tests compare the two bit for bit.
#include <cstdint>
#include <glm/vec3.hpp>

namespace voxc {

// Chris Wellons' "lowbias32" integer finaliser.
constexpr uint32_t mix32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// Streams separate independent draws at one anchor.
enum class RandomStream : uint32_t { RuleChoice = 0, Probability = 1 };

uint32_t anchorHash(uint32_t seed, uint32_t iteration, uint32_t sweep, glm::ivec3 anchorWorld, RandomStream stream);

} // namespace voxc
