// warped_fbm2 (B4.10): without warp it is Eq 3.9; R sets the layer weights; A = 0 gives no noise.
#include "voxc/builtins/Functions.h"
#include "voxc/generators/terrain/Cascade.h"
#include "voxc/generators/terrain/WarpedFbm2.h"

#include <array>
#include <cmath>
#include <gtest/gtest.h>

namespace voxc::terrain {
namespace {

float perlin(float x, float y, uint32_t seed) {
    const std::array<Value, 2> args{Value::makeVec3({x, y, 0.0f}), Value::makeInt(int32_t(seed))};
    return findFunction("perlin3")->eval(args).v.x;
}

// Eq 3.9 with layer weights weight^k, five layers, r = 2.
float unwarped(float x, float y, float weight, uint32_t seed) {
    float sum = 0.0f, amplitude = 1.0f, scale = 1.0f;
    for (int k = 0; k < 5; ++k) {
        sum = sum + amplitude * perlin(x * scale, y * scale, seed);
        amplitude = amplitude * weight;
        scale = scale * 2.0f;
    }
    return sum;
}

TEST(NoiseTest, WithoutWarpItIsEq39) {
    for (int i = 0; i < 50; ++i) {
        const float x = 0.37f * float(i) - 3.1f, y = 0.23f * float(i) + 1.7f;
        EXPECT_EQ(warpedFbm2(x, y, 0.5f, 0.0f, 0.0f, 3), unwarped(x, y, std::exp2(-0.5f), 3));
        EXPECT_EQ(warpedFbm2(x, y, 1.0f, 0.0f, 0.0f, 3), unwarped(x, y, 1.0f, 3)); // R = 1: weights 1
        EXPECT_EQ(warpedFbm2(x, y, 0.0f, 0.0f, 0.0f, 3), unwarped(x, y, 0.5f, 3)); // R = 0: weights 2^-k
    }
}

TEST(NoiseTest, WarpChangesTheFieldAndStaysBounded) {
    int differing = 0;
    for (int i = 0; i < 50; ++i) {
        const float x = 0.41f * float(i), y = 0.19f * float(i) - 2.0f;
        const float warped = warpedFbm2(x, y, 0.5f, 1.0f, 0.5f, 0);
        EXPECT_TRUE(std::isfinite(warped));
        EXPECT_LE(std::abs(warped), 1.04f * 5.0f);
        differing += warped != warpedFbm2(x, y, 0.5f, 0.0f, 0.0f, 0) ? 1 : 0;
    }
    EXPECT_GT(differing, 40);
}

TEST(NoiseTest, ZeroAmplitudeFieldGivesNoNoise) {
    TerrainMap map;
    map.domain.size = 64.0;
    map.domain.minLevel = map.domain.maxLevel = 4;
    map.noise.amplitude = 30.0;
    map.noise.scale = 4.5;
    std::array<Field2, kParamCount> params;
    for (Field2& field : params) field = Field2(16, 16, 0.5f);
    params[size_t(Param::Amplitude)] = Field2(16, 16, 0.0f);
    for (float n : levelNoise(map, 4, params).values) EXPECT_EQ(n, 0.0f);
    params[size_t(Param::Amplitude)] = Field2(16, 16, 1.0f);
    const Field2 noise = levelNoise(map, 4, params);
    EXPECT_NE(noise.values.front(), noise.values.back());
}

TEST(NoiseTest, LevelsSampleOneFieldAtTheirCellCentres) {
    // Cell (i, j) of level L and cell (2^(Lmax-L) (i + 0.5) - 0.5, ...) of level Lmax share a centre
    // only where that is an integer, so compare level 4 against itself through xi: level 4's cell 0
    // centre is xi = 0.5 * 2^(6-4) = 2 final cells.
    TerrainMap map;
    map.domain.size = 64.0;
    map.domain.minLevel = 4;
    map.domain.maxLevel = 6;
    map.noise.amplitude = 64.0;
    map.domain.maxHeight = 64.0;
    map.noise.scale = 100.0;
    std::array<Field2, kParamCount> params;
    for (Field2& field : params) field = Field2(16, 16, 1.0f);
    const Field2 noise = levelNoise(map, 4, params);
    EXPECT_EQ(noise.at(0, 0), warpedFbm2(100.0f * 2.0f / 1000.0f, 100.0f * 2.0f / 1000.0f, 1.0f, 1.0f, 1.0f, 0));
}

} // namespace
} // namespace voxc::terrain
