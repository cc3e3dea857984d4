// Rasterisation of one level (B1.4, B2.9-B2.11): the line, the radius band, signed normal seeds,
// gradient bands with beta falling outwards, overlap removal, parameters on the line.
#include "voxc/generators/terrain/Raster.h"

#include <gtest/gtest.h>

namespace voxc::terrain {
namespace {

// A 64-voxel domain on level 6: cells are one voxel, cell (i, j) centred at (i + 0.5, j + 0.5).
TerrainMap level6Map() {
    TerrainMap map;
    map.domain.size = 64.0;
    map.domain.maxHeight = 64.0;
    map.domain.minLevel = map.domain.maxLevel = 6;
    return map;
}

// A straight spline along +z through cell column `column`, at height y.
Spline straight(double column, double y, MetaPoint meta) {
    Spline spline;
    const double x = column + 0.5;
    spline.controlPoints = {{x, y, -20.0}, {x, y, 10.0}, {x, y, 50.0}, {x, y, 84.0}};
    spline.metaPoints = {meta};
    spline.minLevel = spline.maxLevel = 6;
    return spline;
}

LevelSeeds rasterise(const TerrainMap& map) {
    uint64_t work = 0;
    return rasteriseLevel(map, 6, {}, work);
}

TEST(RasterTest, MetaPointsInterpolateLinearlyAndClampAtTheEnds) {
    Spline spline;
    spline.controlPoints.assign(7, glm::dvec3(0.0));
    MetaPoint a, b;
    a.u = 0.5;
    a.radius = 2.0;
    a.rain = 0.0;
    b.u = 1.5;
    b.radius = 6.0;
    b.rain = 1.0;
    spline.metaPoints = {a, b};
    EXPECT_DOUBLE_EQ(metaAt(spline, 1.0).radius, 4.0);
    EXPECT_DOUBLE_EQ(metaAt(spline, 1.0).rain, 0.5);
    EXPECT_DOUBLE_EQ(metaAt(spline, 0.0).radius, 2.0);
    EXPECT_DOUBLE_EQ(metaAt(spline, 2.0).radius, 6.0);
    spline.metaPoints.clear();
    EXPECT_DOUBLE_EQ(metaAt(spline, 1.0).capacity, MetaPoint{}.capacity); // defaults
}

TEST(RasterTest, RadiusBandSeedsTheElevationAcrossItsWidth) {
    TerrainMap map = level6Map();
    MetaPoint meta;
    meta.radius = 2.0;
    map.splines.push_back(straight(32, 16.0, meta));
    const LevelSeeds seeds = rasterise(map);
    for (int32_t y = 0; y < 64; ++y)
        for (int32_t x = 0; x < 64; ++x) {
            const size_t i = seeds.alpha.index(x, y);
            EXPECT_EQ(seeds.isElevationSeed(i), x >= 30 && x <= 34) << x << "," << y;
            if (seeds.isElevationSeed(i)) {
                EXPECT_EQ(seeds.elevation.values[i], 0.25f);
            } else {
                EXPECT_EQ(seeds.alpha.values[i], 1.0f); // no band: plain averaging
            }
        }
}

TEST(RasterTest, NormalSeedsPointAwayFromTheSpline) {
    TerrainMap map = level6Map();
    map.splines.push_back(straight(32, 0.0, MetaPoint{}));
    const LevelSeeds seeds = rasterise(map);
    for (int32_t y = 0; y < 64; ++y) {
        const size_t left = seeds.normalX.index(31, y), right = seeds.normalX.index(33, y), on = seeds.normalX.index(32, y);
        ASSERT_EQ(seeds.normalSeed[left], 1);
        ASSERT_EQ(seeds.normalSeed[right], 1);
        EXPECT_EQ(seeds.normalSeed[on], 0);
        EXPECT_EQ(seeds.normalX.values[left], -1.0f); // the tangent +z turned towards -x is the left side
        EXPECT_EQ(seeds.normalX.values[right], 1.0f);
        EXPECT_EQ(seeds.normalZ.values[left], 0.0f);
    }
}

TEST(RasterTest, GradientBandsFadeOutwardsWithTheirSlope) {
    TerrainMap map = level6Map();
    MetaPoint meta;
    meta.radius = 1.0;
    meta.left = {8.0, 4.0};    // rise 4 voxels over 8: G = 0.5 * 1 / 64 per cell
    meta.right = {16.0, -8.0}; // fall 8 over 16
    meta.hardness = 0.8;
    map.splines.push_back(straight(32, 32.0, meta));
    const LevelSeeds seeds = rasterise(map);
    const int32_t y = 32;
    float previousBeta = 1.0f;
    for (int32_t x = 30; x >= 25; --x) { // left band: cells 25..30 (edge 31 is the radius seed)
        const size_t i = seeds.alpha.index(x, y);
        ASSERT_FALSE(seeds.isElevationSeed(i)) << x;
        EXPECT_GT(seeds.beta.values[i], 0.0f);
        EXPECT_LT(seeds.beta.values[i], previousBeta);
        EXPECT_LE(seeds.beta.values[i], 0.8f);
        EXPECT_EQ(seeds.alpha.values[i], 1.0f - seeds.beta.values[i]);
        EXPECT_FLOAT_EQ(seeds.gradient.values[i], 0.5f / 64.0f);
        previousBeta = seeds.beta.values[i];
    }
    for (int32_t x = 34; x <= 48; ++x) // right band: cells 34..48
        EXPECT_FLOAT_EQ(seeds.gradient.values[seeds.alpha.index(x, y)], -0.5f / 64.0f) << x;
    EXPECT_EQ(seeds.beta.values[seeds.alpha.index(20, y)], 0.0f); // beyond both bands
    EXPECT_EQ(seeds.beta.values[seeds.alpha.index(55, y)], 0.0f);
}

TEST(RasterTest, OverlappingBandsOfTwoSplinesAreRemoved) {
    TerrainMap map = level6Map();
    MetaPoint meta;
    meta.left = meta.right = {10.0, 5.0};
    meta.hardness = 1.0;
    map.splines.push_back(straight(20, 8.0, meta));
    map.splines.push_back(straight(32, 8.0, meta)); // bands overlap on cells 22..30
    const LevelSeeds seeds = rasterise(map);
    const int32_t y = 32;
    for (int32_t x = 23; x <= 29; ++x) {
        const size_t i = seeds.alpha.index(x, y);
        EXPECT_EQ(seeds.beta.values[i], 0.0f) << x;
        EXPECT_EQ(seeds.alpha.values[i], 1.0f) << x;
    }
    EXPECT_GT(seeds.beta.values[seeds.alpha.index(15, y)], 0.0f); // the outer bands stay
    EXPECT_GT(seeds.beta.values[seeds.alpha.index(37, y)], 0.0f);
}

TEST(RasterTest, ParametersAreSeededOnTheLine) {
    TerrainMap map = level6Map();
    MetaPoint meta;
    meta.noiseAmplitude = 0.75;
    meta.rain = 2.0;
    map.splines.push_back(straight(10, 0.0, meta));
    const LevelSeeds seeds = rasterise(map);
    for (int32_t y = 0; y < 64; ++y)
        for (int32_t x = 0; x < 64; ++x) {
            const size_t i = seeds.alpha.index(x, y);
            ASSERT_EQ(seeds.paramSeed[i], x == 10 ? 1 : 0) << x << "," << y;
            if (x == 10) {
                EXPECT_EQ(seeds.params[size_t(Param::Amplitude)].values[i], 0.75f);
                EXPECT_EQ(seeds.params[size_t(Param::Rain)].values[i], 2.0f);
                EXPECT_EQ(seeds.params[size_t(Param::Capacity)].values[i], 1.0f);
            }
        }
}

} // namespace
} // namespace voxc::terrain
