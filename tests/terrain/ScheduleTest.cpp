// The whole generator (B3.5): cascade, multigrid erosion schedule, drain and final deposit.
#include "voxc/generators/terrain/Terrain.h"

#include <algorithm>
#include <gtest/gtest.h>

namespace voxc::terrain {
namespace {

TerrainMap valleyMap() {
    TerrainMap map;
    map.domain.size = 256.0;
    map.domain.maxHeight = 64.0;
    map.domain.minLevel = 2;
    map.domain.maxLevel = 6;
    map.noise.amplitude = 4.0;
    map.noise.scale = 8.0;
    Spline ridge;
    ridge.controlPoints = {{20, 50, 30}, {100, 60, 60}, {160, 40, 200}, {240, 55, 230}};
    MetaPoint meta;
    meta.radius = 6.0;
    meta.left = meta.right = {40.0, -30.0};
    meta.hardness = 0.8;
    meta.noiseAmplitude = 1.0;
    ridge.metaPoints = {meta};
    ridge.minLevel = 2;
    ridge.maxLevel = 6;
    map.splines.push_back(ridge);
    return map;
}

ErosionSettings smallErosion(uint32_t drainSteps) {
    ErosionSettings erosion = presetSettings("mountain_river");
    erosion.params.radiusMin = 2.0f; // drops scaled to a 64^2 grid
    erosion.params.radiusMax = 6.0f;
    erosion.levelSteps = {{5, 60}, {6, 40}};
    erosion.drainSteps = drainSteps;
    return erosion;
}

float maxOf(const Field2& field) { return *std::max_element(field.values.begin(), field.values.end()); }

TEST(ScheduleTest, HeightIsCascadePlusNoisePlusErodedDifference) {
    const TerrainMap map = valleyMap();
    const TerrainResult plain = generateTerrain(map, std::nullopt);
    const TerrainResult eroded = generateTerrain(map, smallErosion(100));
    ASSERT_EQ(eroded.height.width, 64);
    EXPECT_EQ(plain.erosionSteps, 0u);
    EXPECT_EQ(eroded.erosionSteps, 60u + 40u + 100u);
    EXPECT_EQ(eroded.erosionCellSteps, 60u * 32 * 32 + 40u * 64 * 64 + 100u * 64 * 64);
    bool changed = false;
    for (size_t i = 0; i < plain.height.values.size(); ++i) {
        ASSERT_EQ(eroded.height.values[i], plain.height.values[i] + eroded.difference.values[i]);
        changed = changed || eroded.difference.values[i] != 0.0f;
    }
    EXPECT_TRUE(changed);
}

TEST(ScheduleTest, DrainAndFinalDepositEmptyTheMap) {
    const TerrainResult undrained = generateTerrain(valleyMap(), smallErosion(0));
    const TerrainResult drained = generateTerrain(valleyMap(), smallErosion(100));
    ASSERT_GT(maxOf(undrained.water), 0.0f);
    EXPECT_LE(maxOf(drained.water), 1e-6f * maxOf(undrained.water));
    for (float s : drained.sediment.values) ASSERT_EQ(s, 0.0f);
    EXPECT_EQ(drained.totalSediment, 0.0);
}

TEST(ScheduleTest, RunsAreDeterministic) {
    const TerrainResult a = generateTerrain(valleyMap(), smallErosion(20));
    const TerrainResult b = generateTerrain(valleyMap(), smallErosion(20));
    EXPECT_EQ(a.height.values, b.height.values);
    EXPECT_EQ(a.water.values, b.water.values);
}

TEST(ScheduleTest, GaussianKeepsConstantsAndSmooths) {
    const Field2 constant = gaussian5(Field2(9, 7, 0.5f));
    for (float v : constant.values) EXPECT_EQ(v, 0.5f);
    Field2 spike(9, 9);
    spike.at(4, 4) = 273.0f;
    const Field2 smoothed = gaussian5(spike);
    EXPECT_EQ(smoothed.at(4, 4), 41.0f); // the centre tap
    EXPECT_EQ(smoothed.at(2, 2), 1.0f);  // a corner tap
    double total = 0.0;
    for (float v : smoothed.values) total += v;
    EXPECT_EQ(total, 273.0); // away from the edges the kernel sums to 273/273
}

} // namespace
} // namespace voxc::terrain
