// Presets load Table 5.2/5.3 verbatim; unstable or out-of-range parameters and oversized work are
// rejected with typed errors that name the parameter and carry the numbers.
#include "voxc/generators/terrain/Terrain.h"

#include <gtest/gtest.h>
#include <limits>

namespace voxc::terrain {
namespace {

struct TableRow {
    const char* name;
    float g, kc, ks, kd, ke, iMax, iMin, rMax, rMin, dt;
    std::map<int32_t, uint32_t> steps;
};

TEST(ParametersTest, PresetsAreTable52AndTable53Verbatim) {
    const TableRow rows[] = {
        {"fantasy", 4.36f, 0.9f, 0.7f, 0.882f, 0.12f, 0.4f, 0.24f, 32.0f, 20.8f, 0.2f, {{8, 0}, {9, 547}, {10, 1000}, {11, 0}}},
        {"mountain_range", 3.48f, 1.0f, 0.525f, 0.812f, 0.15f, 0.5f, 0.276f, 35.0f, 15.0f, 0.2f, {{8, 500}, {9, 500}, {10, 500}, {11, 0}}},
        {"mountain_river", 6.0f, 1.0f, 1.0f, 1.0f, 0.15f, 0.18f, 0.08f, 50.0f, 16.4f, 0.25f, {{8, 2000}, {9, 2000}, {10, 1000}, {11, 500}}},
        {"combined", 2.0f, 0.9f, 0.69f, 0.46f, 0.1f, 0.36f, 0.2f, 29.7f, 15.4f, 0.1f, {{8, 1000}, {9, 200}, {10, 100}, {11, 0}}},
    };
    ASSERT_EQ(presets().size(), std::size(rows));
    for (const TableRow& row : rows) {
        SCOPED_TRACE(row.name);
        const ErosionSettings settings = presetSettings(row.name);
        const ErosionParams& p = settings.params;
        EXPECT_EQ(p.pipeArea, 1.0f);
        EXPECT_EQ(p.pipeLength, 1.0f);
        EXPECT_EQ(p.cellSize, 1.0f);
        EXPECT_EQ(p.gravity, row.g);
        EXPECT_EQ(p.capacity, row.kc);
        EXPECT_EQ(p.suspension, row.ks);
        EXPECT_EQ(p.deposition, row.kd);
        EXPECT_EQ(p.evaporation, row.ke);
        EXPECT_EQ(p.rainMax, row.iMax);
        EXPECT_EQ(p.rainMin, row.iMin);
        EXPECT_EQ(p.radiusMax, row.rMax);
        EXPECT_EQ(p.radiusMin, row.rMin);
        EXPECT_EQ(p.dt, row.dt);
        EXPECT_EQ(p.depthLimit, 0.15f);
        EXPECT_EQ(settings.levelSteps, row.steps);
        EXPECT_EQ(settings.drainSteps, 100u);
        EXPECT_NO_THROW(validateErosion(p)); // every preset is stable
    }
}

TEST(ParametersTest, UnknownPresetIsAParameterError) {
    EXPECT_EQ(findPreset("mountain"), nullptr);
    EXPECT_THROW(presetSettings("mountain"), ParameterError);
}

// The parameter the error names for params changed by `change`.
template <class Change>
std::string rejected(Change change) {
    ErosionParams params = findPreset("combined")->params;
    change(params);
    try {
        validateErosion(params);
    } catch (const ParameterError& error) {
        return error.parameter;
    }
    return "(accepted)";
}

TEST(ParametersTest, UnstableCombinationsAreRejectedByName) {
    EXPECT_EQ(rejected([](ErosionParams& p) { p.evaporation = 11.0f; }), "K_e*dt"); // dt = 0.1
    EXPECT_EQ(rejected([](ErosionParams& p) { p.deposition = 20.0f; }), "K_d*dt");
    EXPECT_EQ(rejected([](ErosionParams& p) { p.dt = 0.0f; }), "dt");
    EXPECT_EQ(rejected([](ErosionParams& p) { p.dt = -0.1f; }), "dt");
    EXPECT_EQ(rejected([](ErosionParams& p) { p.pipeLength = 0.0f; }), "pipe_length");
    EXPECT_EQ(rejected([](ErosionParams& p) { p.cellSize = 0.0f; }), "cell_size");
    EXPECT_EQ(rejected([](ErosionParams& p) { p.gravity = std::numeric_limits<float>::quiet_NaN(); }), "gravity");
    EXPECT_EQ(rejected([](ErosionParams& p) { p.rainMin = 1.0f; }), "rain_min");
    EXPECT_EQ(rejected([](ErosionParams& p) { p.radiusMin = 100.0f; }), "radius_min");
    EXPECT_EQ(rejected([](ErosionParams& p) { p.depthLimit = 0.0f; }), "E");
    EXPECT_EQ(rejected([](ErosionParams& p) { p.depthLimit = std::numeric_limits<float>::infinity(); }), "(accepted)");
    EXPECT_EQ(rejected([](ErosionParams& p) { p.evaporation = 10.0f; }), "(accepted)"); // K_e*dt = 1 exactly is stable
}

TEST(ParametersTest, ErrorsCarryTheNumbers) {
    ErosionParams params = findPreset("combined")->params;
    params.evaporation = 20.0f;
    try {
        validateErosion(params);
        FAIL() << "accepted";
    } catch (const ParameterError& error) {
        EXPECT_NEAR(error.value, 2.0, 1e-6);
        EXPECT_NE(std::string(error.what()).find("K_e*dt"), std::string::npos);
    }
}

TerrainMap smallMap() {
    TerrainMap map;
    map.domain.size = 64.0;
    map.domain.minLevel = 2;
    map.domain.maxLevel = 6;
    return map;
}

TEST(ParametersTest, MapValuesAreValidated) {
    TerrainMap map = smallMap();
    map.domain.maxLevel = 13;
    EXPECT_THROW(validateMap(map, {}), ParameterError);
    map = smallMap();
    map.domain.maxHeight = 0.0;
    EXPECT_THROW(validateMap(map, {}), ParameterError);
    map = smallMap();
    map.splines.push_back({{{0, 0, 0}, {1, 0, 1}, {2, 0, 2}}, {}, 2, 6, 300}); // 3 control points
    EXPECT_THROW(validateMap(map, {}), ParameterError);
    map = smallMap();
    MetaPoint meta;
    meta.hardness = 1.5; // alpha + beta would exceed 1
    map.splines.push_back({{{0, 0, 0}, {1, 0, 1}, {2, 0, 2}, {3, 0, 3}}, {meta}, 2, 6, 300});
    try {
        validateMap(map, {});
        FAIL() << "accepted";
    } catch (const ParameterError& error) {
        EXPECT_EQ(error.parameter, "hardness");
        EXPECT_EQ(error.value, 1.5);
    }
}

TEST(ParametersTest, WorkOverTheLimitsIsRejectedBeforeItRuns) {
    TerrainMap map = smallMap();
    Limits limits;
    limits.maxDiffusionCellUpdates = 1000;
    try {
        validateMap(map, limits);
        FAIL() << "accepted";
    } catch (const LimitError& error) {
        EXPECT_EQ(error.limit, 1000u);
        EXPECT_GT(error.value, 1000u);
    }
    ErosionSettings erosion = presetSettings("mountain_river");
    erosion.levelSteps = {{6, 100}};
    limits = Limits{};
    limits.maxErosionCellSteps = 4096 * 150; // 100 steps + 100 drain steps at 64^2 need 4096 * 200
    EXPECT_THROW(generateTerrain(map, erosion, limits), LimitError);
    erosion.levelSteps = {{8, 1}}; // above the map's levels
    EXPECT_THROW(generateTerrain(map, erosion, {}), ParameterError);
}

TEST(ParametersTest, RasterWorkIsBounded) {
    TerrainMap map = smallMap();
    MetaPoint wide;
    wide.radius = 1e6; // every quad covers the whole grid
    map.splines.push_back({{{0, 0, 0}, {20, 0, 20}, {40, 0, 40}, {60, 0, 60}}, {wide}, 2, 6, 4000});
    Limits limits;
    limits.maxRasterCells = 1'000'000;
    try {
        runCascade(map, limits);
        FAIL() << "accepted";
    } catch (const LimitError& error) {
        EXPECT_EQ(error.limit, limits.maxRasterCells);
    }
}

} // namespace
} // namespace voxc::terrain
