// The diffusion cascade (B4.8, B4.9): seeds stay fixed, the maximum principle, level ranges, the
// fixed point after many sweeps, exact prolongation of linear fields, the guided gradient.
#include "voxc/generators/terrain/Cascade.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

namespace voxc::terrain {
namespace {

// A 64-voxel domain (level 6 has 1-voxel cells), heights up to 64.
TerrainMap baseMap(int32_t minLevel, int32_t maxLevel) {
    TerrainMap map;
    map.domain.size = 64.0;
    map.domain.maxHeight = 64.0;
    map.domain.minLevel = minLevel;
    map.domain.maxLevel = maxLevel;
    return map;
}

Spline ridge(double x0, double y0, double x1, double y1, int32_t minLevel, int32_t maxLevel, double radius) {
    Spline spline;
    spline.controlPoints = {{x0, y0, 8.0}, {x0 + (x1 - x0) / 3, y0, 24.0}, {x0 + 2 * (x1 - x0) / 3, y1, 40.0}, {x1, y1, 56.0}};
    MetaPoint meta;
    meta.radius = radius;
    spline.metaPoints = {meta};
    spline.minLevel = minLevel;
    spline.maxLevel = maxLevel;
    return spline;
}

size_t seedCount(const LevelSeeds& seeds) {
    size_t count = 0;
    for (size_t i = 0; i < seeds.alpha.values.size(); ++i) count += seeds.isElevationSeed(i) ? 1 : 0;
    return count;
}

TEST(CascadeTest, SplineSeedsExactlyTheLevelsOfItsRange) {
    TerrainMap map = baseMap(2, 8);
    map.splines.push_back(ridge(10, 20, 50, 30, 4, 6, 0.0));
    uint64_t work = 0;
    for (int32_t level = 2; level <= 8; ++level) {
        const LevelSeeds seeds = rasteriseLevel(map, level, {}, work);
        EXPECT_EQ(seeds.alpha.width, 1 << level);
        EXPECT_EQ(seedCount(seeds) > 0, level >= 4 && level <= 6) << "level " << level;
    }
}

TEST(CascadeTest, SeedsStayFixedAndValuesStayWithinTheSeedRange) {
    TerrainMap map = baseMap(6, 6);
    map.splines.push_back(ridge(10, 40, 50, 10, 6, 6, 2.0)); // heights 40 -> 10 of 64
    uint64_t work = 0;
    const LevelSeeds seeds = rasteriseLevel(map, 6, {}, work);
    ASSERT_GT(seedCount(seeds), 0u);
    const float lowest = std::min(0.0f, *std::min_element(seeds.elevation.values.begin(), seeds.elevation.values.end()));
    const float highest = std::max(0.0f, *std::max_element(seeds.elevation.values.begin(), seeds.elevation.values.end()));
    Field2 v(64, 64), next(64, 64);
    for (int sweep = 0; sweep < 300; ++sweep) {
        terrainSweep(seeds, seeds.normalX, seeds.normalZ, false, v, next);
        std::swap(v, next);
        for (size_t i = 0; i < v.values.size(); ++i) {
            if (seeds.isElevationSeed(i)) {
                ASSERT_EQ(v.values[i], seeds.elevation.values[i]);
            }
            ASSERT_GE(v.values[i], lowest);
            ASSERT_LE(v.values[i], highest);
        }
    }
}

TEST(CascadeTest, WholeCascadeKeepsTheMaximumPrinciple) {
    TerrainMap map = baseMap(2, 7);
    map.splines.push_back(ridge(5, 50, 60, 20, 2, 4, 3.0)); // coarse-only ridge
    map.splines.push_back(ridge(50, 5, 10, 30, 5, 7, 1.0));
    float lowest = 0.0f, highest = 0.0f;
    uint64_t work = 0;
    for (int32_t level = 2; level <= 7; ++level) {
        const LevelSeeds seeds = rasteriseLevel(map, level, {}, work);
        for (float s : seeds.elevation.values) {
            lowest = std::min(lowest, s);
            highest = std::max(highest, s);
        }
    }
    int32_t levels = 0;
    runCascade(map, {}, [&](const LevelFields& fields) {
        ++levels;
        for (float v : fields.height.values) {
            ASSERT_GE(v, lowest);
            ASSERT_LE(v, highest);
        }
    });
    EXPECT_EQ(levels, 6);
}

TEST(CascadeTest, CoarseOnlySplineSurvivesOnTheFinestLevel) {
    // The reason the cascade stays non-converged (B3.2): a ridge seeded only on levels 2..4 still
    // raises the level-7 terrain.
    TerrainMap map = baseMap(2, 7);
    map.splines.push_back(ridge(32, 48, 32, 48, 2, 4, 4.0));
    const LevelFields last = runCascade(map, {});
    EXPECT_GT(*std::max_element(last.height.values.begin(), last.height.values.end()), 0.2f);
}

TEST(CascadeTest, ManySweepsReachTheFixedPoint) {
    TerrainMap map = baseMap(6, 6);
    map.splines.push_back(ridge(10, 40, 50, 10, 6, 6, 2.0));
    uint64_t work = 0;
    const LevelSeeds seeds = rasteriseLevel(map, 6, {}, work);
    Field2 v(64, 64), next(64, 64);
    for (int sweep = 0; sweep < 20000; ++sweep) {
        terrainSweep(seeds, seeds.normalX, seeds.normalZ, false, v, next);
        std::swap(v, next);
    }
    terrainSweep(seeds, seeds.normalX, seeds.normalZ, false, v, next);
    float residual = 0.0f;
    for (size_t i = 0; i < v.values.size(); ++i) residual = std::max(residual, std::abs(next.values[i] - v.values[i]));
    EXPECT_LE(residual, 1e-6f);
}

TEST(CascadeTest, ProlongationIsExactForConstantAndLinearFields) {
    Field2 constant(8, 8, 0.375f), linear(8, 8);
    for (int32_t y = 0; y < 8; ++y)
        for (int32_t x = 0; x < 8; ++x) linear.at(x, y) = 0.25f * float(x) - 0.125f * float(y) + 1.0f;
    const Field2 fineConstant = prolong(constant, false), fineLinear = prolong(linear, false);
    ASSERT_EQ(fineLinear.width, 16);
    for (int32_t y = 1; y < 15; ++y)
        for (int32_t x = 1; x < 15; ++x) {
            EXPECT_EQ(fineConstant.at(x, y), 0.375f);
            // Fine centre (x + 0.5) / 2 - 0.5 in coarse cells.
            const float cx = (float(x) + 0.5f) * 0.5f - 0.5f, cy = (float(y) + 0.5f) * 0.5f - 0.5f;
            EXPECT_EQ(fineLinear.at(x, y), 0.25f * cx - 0.125f * cy + 1.0f) << x << "," << y;
        }
    // Alg. 4 puts coarse cell i's value on fine cell 2i: the half-cell shift of B2.12.
    const Field2 thesis = prolong(linear, true);
    EXPECT_EQ(thesis.at(4, 4), linear.at(2, 2));
}

TEST(CascadeTest, GuidedGradientRisesAwayFromTheSpline) {
    // B4.9: a straight spline along z at cell 32, r = 2 cells, bands 16 cells rising 0.25 max_height.
    TerrainMap map = baseMap(6, 6);
    Spline spline;
    spline.controlPoints = {{32.5, 0, -20}, {32.5, 0, 10}, {32.5, 0, 50}, {32.5, 0, 84}};
    MetaPoint meta;
    meta.radius = 2.0;
    meta.left = {16.0, 16.0}; // (width, rise) in world voxels: 0.25 * max_height
    meta.right = {16.0, 16.0};
    meta.hardness = 1.0;
    spline.metaPoints = {meta};
    spline.minLevel = spline.maxLevel = 6;
    map.splines.push_back(spline);
    map.diffusion.multiplier = 20000.0 / 6.0;
    ASSERT_EQ(terrainSweeps(map.diffusion, 6), 20000u);
    const LevelFields fields = runCascade(map, {});
    // Bands: cells 35..50 right and 14..29 left; beta falls to 0 at the outer edge, where the fixed point
    // is flat (v50 = v49 exactly in real arithmetic, within an ulp in float32).
    for (int32_t y = 8; y < 56; ++y) {
        for (int32_t x = 34; x < 50; ++x) ASSERT_GE(fields.height.at(x + 1, y), fields.height.at(x, y) - 1e-6f) << x << "," << y;
        for (int32_t x = 30; x > 14; --x) ASSERT_GE(fields.height.at(x - 1, y), fields.height.at(x, y) - 1e-6f) << x << "," << y;
        for (int32_t x = 34; x < 44; ++x) ASSERT_GT(fields.height.at(x + 1, y), fields.height.at(x, y)) << x << "," << y;
        for (int32_t x = 30; x > 20; --x) ASSERT_GT(fields.height.at(x - 1, y), fields.height.at(x, y)) << x << "," << y;
        EXPECT_GT(fields.height.at(50, y) - fields.height.at(34, y), 0.1f); // most of the 0.25 rise
        EXPECT_GT(fields.height.at(14, y) - fields.height.at(30, y), 0.1f);
    }
}

// Rise of the converged band per world voxel of distance from a diagonal spline (B2.8's anisotropy).
double diagonalBandSlope(bool isotropic) {
    TerrainMap map = baseMap(6, 6);
    Spline spline;
    spline.controlPoints = {{-16, 0, -16}, {16, 0, 16}, {48, 0, 48}, {80, 0, 80}};
    MetaPoint meta;
    meta.radius = 1.0;
    meta.left = meta.right = {24.0, 6.0}; // 0.25 voxels per voxel
    meta.hardness = 1.0;
    spline.metaPoints = {meta};
    spline.minLevel = spline.maxLevel = 6;
    map.splines.push_back(spline);
    map.diffusion.multiplier = 20000.0 / 6.0;
    map.diffusion.isotropicGradient = isotropic;
    const LevelFields fields = runCascade(map, {});
    // Cells (32 + k, 31 - k) step sqrt(2) voxels away from the line per k; compare k = 3 and k = 7.
    const double rise = (fields.height.at(39, 24) - fields.height.at(35, 28)) * map.domain.maxHeight;
    return rise / (4.0 * std::sqrt(2.0));
}

TEST(CascadeTest, IsotropicGradientRemovesTheDiagonalSteepening) {
    const double plain = diagonalBandSlope(false), isotropic = diagonalBandSlope(true);
    EXPECT_NEAR(isotropic, 0.25, 0.25 * 0.05);
    EXPECT_NEAR(plain, 0.25 * std::sqrt(2.0), 0.25 * std::sqrt(2.0) * 0.05); // G / (|N_x|^3 + |N_y|^3)
}

TEST(CascadeTest, SweepCountsFollowTheIterationRule) {
    DiffusionSettings settings;
    settings.multiplier = 0.89; // Mountain river
    EXPECT_EQ(terrainSweeps(settings, 11), 10u); // floor(11 * 0.89 + 0.5)
    EXPECT_EQ(fieldSweeps(settings, 11), 5u);
    settings.rule = IterationRule::Side;
    EXPECT_EQ(terrainSweeps(settings, 11), 1823u);
    settings.multiplier = 0.0;
    EXPECT_EQ(terrainSweeps(settings, 11), 1u);
    EXPECT_EQ(fieldSweeps(settings, 11), 1u);
}

} // namespace
} // namespace voxc::terrain
