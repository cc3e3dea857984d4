// Fractals, warps and curl built on perlin3 (mirror: noise_fractal.glsl).
#include "Noise.h"
#include "NoiseCommon.h"

#include <algorithm>

namespace voxc::noise {

namespace {

int32_t octaveCount(int32_t octaves) { return std::min(std::max(octaves, 1), kMaxOctaves); }

glm::vec3 scaled(glm::vec3 p, float s) { return {p.x * s, p.y * s, p.z * s}; }

// The three fractals share the octave loop; `Fold` turns an octave's noise into its term. The
// sum starts at the first octave's term, not at 0 + term: that addition turns -0 into +0, and a
// device may drop an addition of the constant 0 (lavapipe does), keeping -0.
template <typename Fold>
float octaveSum(glm::vec3 p, int32_t octaves, float lacunarity, float gain, uint32_t seed, Fold fold) {
    float sum = 0.0f, amplitude = 1.0f, frequency = 1.0f;
    const int32_t count = octaveCount(octaves);
    for (int32_t k = 0; k < count; ++k) {
        const float n = perlin3(scaled(p, frequency), substream(seed, uint32_t(k)));
        const float weighted = amplitude * fold(n);
        sum = k == 0 ? weighted : sum + weighted;
        amplitude = amplitude * gain;
        frequency = frequency * lacunarity;
    }
    return sum;
}

} // namespace

float fbm(glm::vec3 p, int32_t octaves, float lacunarity, float gain, uint32_t seed) {
    return octaveSum(p, octaves, lacunarity, gain, seed, [](float n) { return n; });
}

float turbulence(glm::vec3 p, int32_t octaves, float lacunarity, float gain, uint32_t seed) {
    return octaveSum(p, octaves, lacunarity, gain, seed, [](float n) { return std::fabs(n); });
}

float ridged(glm::vec3 p, int32_t octaves, float lacunarity, float gain, uint32_t seed) {
    float weight = 1.0f;
    return octaveSum(p, octaves, lacunarity, gain, seed, [&weight](float n) {
        float s = 1.0f - std::fabs(n);
        s = s * s;
        s = s * weight;
        weight = std::min(std::max(s * 2.0f, 0.0f), 1.0f);
        return s;
    });
}

glm::vec3 warp(glm::vec3 p, float amount, uint32_t seed) {
    const float wx = fbm(p, 4, 2.0f, 0.5f, substream(seed, 101));
    const float wy = fbm(p, 4, 2.0f, 0.5f, substream(seed, 102));
    const float wz = fbm(p, 4, 2.0f, 0.5f, substream(seed, 103));
    return {p.x + amount * wx, p.y + amount * wy, p.z + amount * wz};
}

glm::vec3 curl3(glm::vec3 p, uint32_t seed) {
    const uint32_t s1 = substream(seed, 201), s2 = substream(seed, 202), s3 = substream(seed, 203);
    const float e = kCurlEpsilon, inv = 128.0f; // 1 / (2 * e), exact
    const glm::vec3 px{p.x + e, p.y, p.z}, mx{p.x - e, p.y, p.z};
    const glm::vec3 py{p.x, p.y + e, p.z}, my{p.x, p.y - e, p.z};
    const glm::vec3 pz{p.x, p.y, p.z + e}, mz{p.x, p.y, p.z - e};
    const float d3dy = (perlin3(py, s3) - perlin3(my, s3)) * inv;
    const float d2dz = (perlin3(pz, s2) - perlin3(mz, s2)) * inv;
    const float d1dz = (perlin3(pz, s1) - perlin3(mz, s1)) * inv;
    const float d3dx = (perlin3(px, s3) - perlin3(mx, s3)) * inv;
    const float d2dx = (perlin3(px, s2) - perlin3(mx, s2)) * inv;
    const float d1dy = (perlin3(py, s1) - perlin3(my, s1)) * inv;
    return {d3dy - d2dz, d1dz - d3dx, d2dx - d1dy};
}

namespace {

// One layer k of Eq 3.11 with T_pre of Eq 3.12: q = r^k p, w = k F + D / (1 + k),
// S(q + w (S(q + 50), S(q + 150), S(q + 250))). `invOnePlusK` is a literal so no division runs.
float warpedLayer(glm::vec3 q, float k, float invOnePlusK, float warpLow, float warpHigh, uint32_t seed) {
    const float w = k * warpHigh + warpLow * invOnePlusK;
    const float ox = perlin3({q.x + 50.0f, q.y + 50.0f, q.z + 50.0f}, seed);
    const float oy = perlin3({q.x + 150.0f, q.y + 150.0f, q.z + 150.0f}, seed);
    const float oz = perlin3({q.x + 250.0f, q.y + 250.0f, q.z + 250.0f}, seed);
    return perlin3({q.x + w * ox, q.y + w * oy, q.z + w * oz}, seed);
}

} // namespace

float warpedFbm(glm::vec3 p, float roughness, float warpLow, float warpHigh, uint32_t seed) {
    // Amplitude of layer k: 1 / r^(k (1 - R)) = a^k with a = 2^-(1 - R).
    const float a = std::exp2(-(1.0f - roughness));
    float sum = 0.0f, amplitude = 1.0f;
    sum = sum + amplitude * warpedLayer(p, 0.0f, 1.0f, warpLow, warpHigh, seed);
    amplitude = amplitude * a;
    sum = sum + amplitude * warpedLayer(scaled(p, 2.0f), 1.0f, 0.5f, warpLow, warpHigh, seed);
    amplitude = amplitude * a;
    sum = sum + amplitude * warpedLayer(scaled(p, 4.0f), 2.0f, 0.333333343f, warpLow, warpHigh, seed);
    amplitude = amplitude * a;
    sum = sum + amplitude * warpedLayer(scaled(p, 8.0f), 3.0f, 0.25f, warpLow, warpHigh, seed);
    amplitude = amplitude * a;
    sum = sum + amplitude * warpedLayer(scaled(p, 16.0f), 4.0f, 0.2f, warpLow, warpHigh, seed);
    return sum;
}

} // namespace voxc::noise
