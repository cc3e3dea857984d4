#pragma once
// Lattice helpers shared by the noise functions; compiler/shaders/noise_common.glsl mirrors them.
#include "voxc/builtins/Shapes.h"
#include "voxc/program/Random.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace voxc::noise {

inline int perm(int i) { return perlinPermutation()[i & 255]; }

// Perlin's permutation as pairs, as the shaders read it (noise_permutation.glsl): entry i holds
// perm(i) in bits 0..7 and perm(i + 1) in bits 8..15, so one gather serves the two lookups at i
// and i + 1 that perlin3 makes.
inline const std::array<int, 256>& permutationPairs() {
    static const std::array<int, 256> pairs = [] {
        std::array<int, 256> built{};
        for (int i = 0; i < 256; ++i) built[size_t(i)] = perm(i) | perm(i + 1) << 8;
        return built;
    }();
    return pairs;
}

// A lattice cell exists only for finite coordinates: noise of a point with a NaN or infinite
// coordinate is NaN (docs/language.md, "Non-finite values"), never a float -> int conversion
// of a non-finite value.
inline bool finite(glm::vec3 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

inline float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

inline float lerp(float t, float a, float b) { return a + t * (b - a); }

// Perlin's reference gradient: 12 cube-edge directions, four of them repeated (hash & 15).
constexpr float grad(int hash, float x, float y, float z) {
    const int h = hash & 15;
    const float u = h < 8 ? x : y;
    const float v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
    return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
}

// An integer-valued float (a floor) reduced modulo 256: exact for every finite value, so no
// float -> int conversion can overflow however large the coordinate.
inline int latticeIndex(float floored) { return int(floored - 256.0f * std::floor(floored * 0.00390625f)); }

// Seed-derived lattice translation (8 bits per axis; mix32(0) = 0, so seed 0 is untranslated).
// Translating the lattice index instead of the coordinate keeps every bit of precision.
inline int seedOffset(uint32_t seed, int axis) { return int((mix32(seed) >> (8 * axis)) & 255u); }

// A float lattice coordinate as an int for hashing, saturated at +-2^30 (beyond that the
// float spacing exceeds a cell anyway).
inline int32_t hashCoordinate(float floored) { return int32_t(std::fmin(std::fmax(floored, -1073741824.0f), 1073741824.0f)); }

// Hash of a lattice cell; successive mix32 calls give further independent values.
inline uint32_t cellHash(int32_t x, int32_t y, int32_t z, uint32_t seed) {
    return mix32(uint32_t(x) ^ mix32(uint32_t(y) ^ mix32(uint32_t(z) ^ mix32(seed))));
}

// 24 hash bits as a float in [0, 1): exact on both sides.
inline float unitFloat(uint32_t h) { return float(h >> 8) * 5.9604644775390625e-8f; }

} // namespace voxc::noise
