#include "voxc/generators/terrain/Cascade.h"

#include "voxc/generators/terrain/WarpedFbm2.h"

#include <cmath>

namespace voxc::terrain {

void terrainSweep(const LevelSeeds& seeds, const Field2& normalX, const Field2& normalZ, bool isotropicGradient,
                  const Field2& from, Field2& to) {
    const int32_t n = from.width;
    for (int32_t y = 0; y < n; ++y)
        for (int32_t x = 0; x < n; ++x) {
            const size_t i = from.index(x, y);
            const float alpha = seeds.alpha.values[i], beta = seeds.beta.values[i], s = seeds.elevation.values[i];
            if (alpha == 0.0f && beta == 0.0f) { // elevation seed: Dirichlet, bitwise S
                to.values[i] = s;
                continue;
            }
            // Nine-point average, row-major from (x-1, y-1).
            float sum = 0.0f;
            for (int32_t dy = -1; dy <= 1; ++dy)
                for (int32_t dx = -1; dx <= 1; ++dx)
                    if (dx != 0 || dy != 0) sum = sum + from.clamped(x + dx, y + dy);
            const float average = sum * 0.125f;
            if (beta == 0.0f) {
                to.values[i] = alpha * average + (1.0f - alpha) * s;
                continue;
            }
            // B2.8: upwind neighbour along each axis of N, weights N_x^2, N_y^2.
            const float nx = normalX.values[i], nz = normalZ.values[i];
            const float length = std::sqrt(nx * nx + nz * nz);
            float guided = average, gradient = seeds.gradient.values[i];
            if (length >= 1e-6f) {
                const float ux = nx / length, uz = nz / length;
                const int32_t sx = ux > 0.0f ? 1 : (ux < 0.0f ? -1 : 0), sz = uz > 0.0f ? 1 : (uz < 0.0f ? -1 : 0);
                guided = ux * ux * from.clamped(x - sx, y) + uz * uz * from.clamped(x, y - sz);
                if (isotropicGradient) {
                    const float ax = std::abs(ux), az = std::abs(uz);
                    gradient = gradient * (ax * ax * ax + az * az * az);
                }
            }
            to.values[i] = alpha * average + beta * (guided + gradient) + ((1.0f - alpha) - beta) * s;
        }
}

void averageSweep(const std::vector<uint8_t>& seed, const Field2& seedValues, const Field2& from, Field2& to) {
    const int32_t w = from.width, h = from.height;
    for (int32_t y = 0; y < h; ++y)
        for (int32_t x = 0; x < w; ++x) {
            const size_t i = from.index(x, y);
            if (seed[i] != 0) {
                to.values[i] = seedValues.values[i];
                continue;
            }
            const float sum = ((from.clamped(x, y - 1) + from.clamped(x - 1, y)) + from.clamped(x + 1, y)) + from.clamped(x, y + 1);
            to.values[i] = sum * 0.25f;
        }
}

Field2 prolong(const Field2& coarse, bool thesis) {
    Field2 fine(coarse.width * 2, coarse.height * 2);
    for (int32_t y = 0; y < fine.height; ++y)
        for (int32_t x = 0; x < fine.width; ++x) {
            const int32_t cx = x / 2, cy = y / 2;
            float value;
            if (thesis) { // Alg. 4: (I[c] + rx I[c+(1,0)] + ry I[c+(0,1)] + rx ry I[c+(1,1)]) / (1 + rx + ry + rx ry)
                const int32_t rx = x % 2, ry = y % 2;
                float sum = coarse.at(cx, cy);
                if (rx) sum = sum + coarse.clamped(cx + 1, cy);
                if (ry) sum = sum + coarse.clamped(cx, cy + 1);
                if (rx && ry) sum = sum + coarse.clamped(cx + 1, cy + 1);
                value = sum / float((1 + rx) * (1 + ry));
            } else { // the fine centre lies a quarter coarse cell from its parent's, towards neighbour (ox, oy)
                const int32_t ox = (x % 2) ? 1 : -1, oy = (y % 2) ? 1 : -1;
                value = ((0.5625f * coarse.at(cx, cy) + 0.1875f * coarse.clamped(cx + ox, cy)) + 0.1875f * coarse.clamped(cx, cy + oy)) +
                        0.0625f * coarse.clamped(cx + ox, cy + oy);
            }
            fine.at(x, y) = value;
        }
    return fine;
}

Field2 levelNoise(const TerrainMap& map, int32_t level, const std::array<Field2, kParamCount>& params) {
    const int32_t n = int32_t(1) << level;
    Field2 noise(n, n);
    if (map.noise.amplitude == 0.0) return noise;
    const float amplitude = float(map.noise.amplitude / map.domain.maxHeight);
    const float scale = float(map.noise.scale);
    const float finalCellsPerCell = std::ldexp(1.0f, map.domain.maxLevel - level);
    for (int32_t y = 0; y < n; ++y)
        for (int32_t x = 0; x < n; ++x) {
            const size_t i = noise.index(x, y);
            // xi = cell centre in final-level cells (exact in float), so every level samples one field.
            const float xiX = (float(x) + 0.5f) * finalCellsPerCell, xiY = (float(y) + 0.5f) * finalCellsPerCell;
            const float w = warpedFbm2(scale * xiX / 1000.0f, scale * xiY / 1000.0f, params[size_t(Param::Roughness)].values[i],
                                       params[size_t(Param::WarpLow)].values[i], params[size_t(Param::WarpHigh)].values[i], map.noise.seed);
            noise.values[i] = (amplitude * params[size_t(Param::Amplitude)].values[i]) * w;
        }
    return noise;
}

namespace {

// `sweeps` ping-pong sweeps starting from `field`; the result is back in `field`.
template <class Sweep>
void iterate(Field2& field, uint32_t sweeps, Sweep&& sweep) {
    Field2 scratch(field.width, field.height);
    for (uint32_t k = 0; k < sweeps; ++k) {
        sweep(field, scratch);
        std::swap(field, scratch);
    }
}

} // namespace

LevelFields runCascade(const TerrainMap& map, const Limits& limits, const std::function<void(const LevelFields&)>& onLevel) {
    validateMap(map, limits);
    const bool thesis = map.diffusion.thesisProlongation;
    uint64_t rasterCells = 0;
    LevelFields current;
    for (int32_t level = map.domain.minLevel; level <= map.domain.maxLevel; ++level) {
        const LevelSeeds seeds = rasteriseLevel(map, level, limits, rasterCells);
        const int32_t n = int32_t(1) << level;
        LevelFields next;
        next.level = level;
        if (level == map.domain.minLevel) {
            next.height = next.normalX = next.normalZ = Field2(n, n);
            for (Field2& field : next.params) field = Field2(n, n);
        } else {
            next.height = prolong(current.height, thesis);
            next.normalX = prolong(current.normalX, thesis);
            next.normalZ = prolong(current.normalZ, thesis);
            for (size_t p = 0; p < kParamCount; ++p) next.params[p] = prolong(current.params[p], thesis);
        }
        // Normals first: the terrain sweeps of this level use the level's diffused normals.
        const uint32_t half = fieldSweeps(map.diffusion, level);
        iterate(next.normalX, half, [&](const Field2& a, Field2& b) { averageSweep(seeds.normalSeed, seeds.normalX, a, b); });
        iterate(next.normalZ, half, [&](const Field2& a, Field2& b) { averageSweep(seeds.normalSeed, seeds.normalZ, a, b); });
        for (size_t p = 0; p < kParamCount; ++p)
            iterate(next.params[p], half, [&](const Field2& a, Field2& b) { averageSweep(seeds.paramSeed, seeds.params[p], a, b); });
        iterate(next.height, terrainSweeps(map.diffusion, level), [&](const Field2& a, Field2& b) {
            terrainSweep(seeds, next.normalX, next.normalZ, map.diffusion.isotropicGradient, a, b);
        });
        current = std::move(next);
        if (onLevel) onLevel(current);
    }
    return current;
}

} // namespace voxc::terrain
