// Hardening: values at the edges of every documented range give finite fields, never NaN or inf;
// work outside the domain costs nothing; oversized work is refused before it runs.
#include "voxc/generators/terrain/Terrain.h"

#include <cmath>
#include <gtest/gtest.h>

namespace voxc::terrain {
namespace {

bool allFinite(const Field2& field) {
    for (float v : field.values)
        if (!std::isfinite(v)) return false;
    return true;
}

// A checkerboard of extreme heights: the steepest terrain a validated map can produce is far milder.
ErosionGrid spikes(float height) {
    ErosionGrid grid(16, 16);
    for (int32_t y = 0; y < 16; ++y)
        for (int32_t x = 0; x < 16; ++x) grid.base.at(x, y) = ((x + y) % 2 == 0) ? height : -height;
    std::fill(grid.rain.values.begin(), grid.rain.values.end(), 1e3f);
    std::fill(grid.capacity.values.begin(), grid.capacity.values.end(), 1e3f);
    return grid;
}

ErosionParams extreme(bool large) {
    ErosionParams p;
    const float rate = large ? 1e3f : 0.0f;
    p.pipeArea = p.gravity = p.capacity = p.suspension = rate;
    p.pipeLength = p.cellSize = large ? 1e-3f : 1e3f; // short pipes and small cells are the violent end
    p.dt = large ? 1e-4f : 1e2f;
    p.deposition = p.evaporation = large ? 1e3f : 0.01f; // K * dt <= 1 either way
    p.rainMin = p.rainMax = large ? 1e3f : 0.0f;
    p.radiusMin = p.radiusMax = large ? 1e5f : 0.0f;
    p.uniformRain = 1e3f;
    p.depthLimit = large ? std::numeric_limits<float>::infinity() : 1e-3f;
    return p;
}

TEST(RobustnessTest, ErosionAtTheEdgesOfItsRangesStaysFinite) {
    for (bool large : {true, false})
        for (RainMode rain : {RainMode::Drops, RainMode::Uniform})
            for (Transport transport : {Transport::Conservative, Transport::Mei}) {
                ErosionParams params = extreme(large);
                params.rain = rain;
                params.transport = transport;
                ASSERT_NO_THROW(validateErosion(params));
                ErosionGrid grid = spikes(1e15f);
                for (uint32_t step = 0; step < 30; ++step) erosionStep(grid, params, 4, step, step >= 25);
                for (const Field2* field : {&grid.difference, &grid.water, &grid.sediment, &grid.fluxL, &grid.fluxR, &grid.fluxT,
                                            &grid.fluxB, &grid.velocityU, &grid.velocityV})
                    EXPECT_TRUE(allFinite(*field)) << "large " << large << " rain " << int(rain) << " transport " << int(transport);
            }
}

TerrainMap extremeMap() {
    TerrainMap map;
    map.domain.origin = {-5e8, -5e8};
    map.domain.size = 1e9;
    map.domain.maxHeight = 1.0;
    map.domain.minLevel = 1;
    map.domain.maxLevel = 5;
    map.noise.amplitude = 1e9;
    map.noise.scale = 1e6;
    Spline spline;
    spline.controlPoints = {{-1e9, 1e9, -1e9}, {1e9, -1e9, -1e9}, {-1e9, 1e9, 1e9}, {1e9, -1e9, 1e9}};
    MetaPoint thin, wide;
    thin.left = {1e-300, 1e9}; // narrower than any cell
    thin.right = {1e9, -1e9};
    thin.hardness = 1.0;
    thin.noiseAmplitude = 1e3;
    thin.warpLow = thin.warpHigh = -1e3;
    thin.noiseRoughness = 1.0;
    wide = thin;
    wide.u = 1.0;
    wide.radius = 1e9;
    wide.rain = wide.capacity = 1e3;
    spline.metaPoints = {thin, wide};
    spline.minLevel = 1;
    spline.maxLevel = 5;
    map.splines.push_back(spline);
    map.diffusion.multiplier = 40.0;
    return map;
}

TEST(RobustnessTest, CascadeAtTheEdgesOfItsRangesStaysFinite) {
    const TerrainMap map = extremeMap();
    runCascade(map, {}, [&](const LevelFields& fields) {
        EXPECT_TRUE(allFinite(fields.height)) << "level " << fields.level;
        EXPECT_TRUE(allFinite(levelNoise(map, fields.level, fields.params))) << "level " << fields.level;
        for (const Field2& param : fields.params) EXPECT_TRUE(allFinite(param));
    });
    ErosionSettings erosion = presetSettings("combined");
    erosion.levelSteps = {{4, 20}, {5, 20}};
    erosion.drainSteps = 10;
    const TerrainResult result = generateTerrain(map, erosion);
    EXPECT_TRUE(allFinite(result.height));
    EXPECT_TRUE(std::isfinite(result.totalWater));
}

TEST(RobustnessTest, OutOfRangeMapValuesAreRejected) {
    auto rejects = [](auto change) {
        TerrainMap map = extremeMap();
        change(map);
        EXPECT_THROW(validateMap(map, {}), ParameterError);
    };
    rejects([](TerrainMap& m) { m.domain.maxHeight = 0.5; });
    rejects([](TerrainMap& m) { m.domain.size = 1e10; });
    rejects([](TerrainMap& m) { m.splines[0].controlPoints[1].y = 2e9; });
    rejects([](TerrainMap& m) { m.splines[0].controlPoints[2].x = std::nan(""); });
    rejects([](TerrainMap& m) { m.splines[0].metaPoints[0].warpLow = 1e4; });
    rejects([](TerrainMap& m) { m.splines[0].metaPoints[0].noiseRoughness = 1.5; });
    rejects([](TerrainMap& m) { m.splines[0].metaPoints[0].rain = -1.0; });
    rejects([](TerrainMap& m) { m.splines[0].metaPoints[1].u = 1.5; }); // past the one piece
    rejects([](TerrainMap& m) { m.noise.scale = std::numeric_limits<double>::infinity(); });
}

TEST(RobustnessTest, SplinesOutsideTheDomainCostNothing) {
    TerrainMap map;
    map.domain.size = 64.0;
    map.domain.minLevel = map.domain.maxLevel = 12;
    Spline far;
    far.controlPoints = {{1e9, 0, 1e9}, {1e9 + 10, 0, 1e9}, {1e9 + 20, 0, 1e9}, {1e9 + 30, 0, 1e9}};
    far.minLevel = 0;
    far.maxLevel = 12;
    map.splines.push_back(far);
    uint64_t work = 0;
    const LevelSeeds seeds = rasteriseLevel(map, 12, {}, work);
    EXPECT_EQ(work, 0u);
    EXPECT_EQ(seeds.alpha.width, 4096);
}

TEST(RobustnessTest, TooManySplineSamplesAreRefusedBeforeWork) {
    TerrainMap map;
    map.domain.size = 64.0;
    Spline spline;
    for (int i = 0; i < 3 * 1024 + 1; ++i) spline.controlPoints.push_back({double(i % 64), 0.0, double(i / 64)});
    spline.samplings = 4096;
    spline.minLevel = 2;
    spline.maxLevel = 11;
    map.splines.assign(4, spline); // 4 * 10 levels * 1024 pieces * 4096 samples
    try {
        validateMap(map, {});
        FAIL() << "accepted";
    } catch (const LimitError& error) {
        EXPECT_EQ(error.value, 4u * 10 * 1024 * 4096);
        EXPECT_EQ(error.limit, Limits{}.maxSplineSamples);
    }
}

} // namespace
} // namespace voxc::terrain
