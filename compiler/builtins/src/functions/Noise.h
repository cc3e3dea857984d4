#pragma once
// The interpreter's noise functions. Each has a GLSL mirror in compiler/shaders/noise_*.glsl
// that performs the same IEEE operations in the same order (every float result `precise`
// there, -ffp-contract=off here), so both sides agree to the record's tolerance.
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace voxc::noise {

// Fractal octave counts are clamped to 1..kMaxOctaves.
constexpr int32_t kMaxOctaves = 16;

// A seed for an independent sub-field (octave k, warp component c, ...): seed + stream * golden ratio.
uint32_t substream(uint32_t seed, uint32_t stream);

// Ken Perlin's improved noise (2002); seed 0 is exactly the reference, other seeds translate
// the lattice by a seed-derived integer offset. Range about [-1.04, 1.04].
float perlin3(glm::vec3 p, uint32_t seed);
// 3D simplex noise (kernel radius^2 0.5, Perlin's 12 gradients); range about [-1, 1].
float simplex3(glm::vec3 p, uint32_t seed);
// Quintic interpolation of mix32-hashed lattice values in [-1, 1).
float value3(glm::vec3 p, uint32_t seed);
// (F1, F2): distances to the nearest and second-nearest feature point, one per cell, 27 cells.
glm::vec2 worley3(glm::vec3 p, uint32_t seed);
// Curl of (perlin3 x3, decorrelated) by central differences with step kCurlEpsilon.
constexpr float kCurlEpsilon = 0.00390625f; // 1/256: p +- eps is exact for |p| < 2^15
glm::vec3 curl3(glm::vec3 p, uint32_t seed);

// Sum over octaves k < clamp(octaves, 1, 16) of gain^k * n_k(p * lacunarity^k), n_k = perlin3 of substream k:
float fbm(glm::vec3 p, int32_t octaves, float lacunarity, float gain, uint32_t seed);
// ... of gain^k * s_k, s_k = (1 - |n_k|)^2 * w_k, w_0 = 1, w_{k+1} = clamp(2 s_k, 0, 1).
float ridged(glm::vec3 p, int32_t octaves, float lacunarity, float gain, uint32_t seed);
// ... of gain^k * |n_k|.
float turbulence(glm::vec3 p, int32_t octaves, float lacunarity, float gain, uint32_t seed);

// p + amount * (three fbm fields: 4 octaves, lacunarity 2, gain 0.5, substreams 101..103).
glm::vec3 warp(glm::vec3 p, float amount, uint32_t seed);
// Mathisen's warped fBm (thesis Eq 3.11/3.12, A = 1, n = 4, r = 2, offsets 50/150/250); see docs/functions.md.
float warpedFbm(glm::vec3 p, float roughness, float warpLow, float warpHigh, uint32_t seed);
// The two-argument form's parameters.
constexpr float kWarpedFbmRoughness = 0.0f, kWarpedFbmWarpLow = 1.0f, kWarpedFbmWarpHigh = 0.5f;

} // namespace voxc::noise
