// Hashed-lattice noise: value noise and Worley noise (mirrors: noise_value3.glsl, noise_worley3.glsl).
#include "Noise.h"
#include "NoiseCommon.h"

namespace voxc::noise {

namespace {

// The lattice value at a cell, in [-1, 1).
float latticeValue(int32_t x, int32_t y, int32_t z, uint32_t seed) {
    return float(cellHash(x, y, z, seed) >> 8) * 1.1920928955078125e-7f - 1.0f;
}

} // namespace

float value3(glm::vec3 p, uint32_t seed) {
    if (!finite(p)) return kNaN;
    const float fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
    const int32_t X = hashCoordinate(fx), Y = hashCoordinate(fy), Z = hashCoordinate(fz);
    const float u = fade(p.x - fx), v = fade(p.y - fy), w = fade(p.z - fz);
    const float l00 = lerp(u, latticeValue(X, Y, Z, seed), latticeValue(X + 1, Y, Z, seed));
    const float l10 = lerp(u, latticeValue(X, Y + 1, Z, seed), latticeValue(X + 1, Y + 1, Z, seed));
    const float l01 = lerp(u, latticeValue(X, Y, Z + 1, seed), latticeValue(X + 1, Y, Z + 1, seed));
    const float l11 = lerp(u, latticeValue(X, Y + 1, Z + 1, seed), latticeValue(X + 1, Y + 1, Z + 1, seed));
    return lerp(w, lerp(v, l00, l10), lerp(v, l01, l11));
}

glm::vec2 worley3(glm::vec3 p, uint32_t seed) {
    if (!finite(p)) return glm::vec2(kNaN);
    const float fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
    const int32_t X = hashCoordinate(fx), Y = hashCoordinate(fy), Z = hashCoordinate(fz);
    // Distances are taken in cell-local coordinates so they keep full precision far from 0.
    const float x = p.x - fx, y = p.y - fy, z = p.z - fz;
    float f1 = 100.0f, f2 = 100.0f; // squared; every candidate is closer than 100
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const uint32_t hx = cellHash(X + dx, Y + dy, Z + dz, seed);
                const uint32_t hy = mix32(hx);
                const uint32_t hz = mix32(hy);
                const float ox = float(dx) + unitFloat(hx) - x;
                const float oy = float(dy) + unitFloat(hy) - y;
                const float oz = float(dz) + unitFloat(hz) - z;
                const float d = ox * ox + oy * oy + oz * oz;
                if (d < f1) {
                    f2 = f1;
                    f1 = d;
                } else if (d < f2) {
                    f2 = d;
                }
            }
    return {std::sqrt(f1), std::sqrt(f2)};
}

} // namespace voxc::noise
