// Sampling a terrain's map from fields (voxc/program/SampledMap.h): the bilinear rule on maps
// whose values are known, the range rule against brute force, and the checker's reading of
// NAME(wx, wz) (located errors, the node it builds, column hoisting; the heights come with the
// run's solve, never the check).
#include "voxc/check/Check.h"
#include "voxc/ir/Lower.h"
#include "voxc/program/SampledMap.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Solve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace voxc {
namespace {

// h = 3 + 0.5·i − 0.25·j at cell centre (i, j); cells of 2 voxels from world (−8, 4).
SampledMap linearMap() {
    SampledMap map;
    map.name = "m";
    map.size = {8, 1, 8};
    map.origin = {-8.0f, 0.0f, 4.0f};
    map.cellsPerVoxel = {0.5f, 1.0f, 0.5f};
    for (int j = 0; j < map.size.z; ++j)
        for (int i = 0; i < map.size.x; ++i) map.values.push_back(3.0f + 0.5f * float(i) - 0.25f * float(j));
    map.lowest = 3.0f - 0.25f * 7.0f;
    map.highest = 3.0f + 0.5f * 7.0f;
    return map;
}

TEST(terrain_MapSample, BilinearReproducesALinearMapBetweenCellCentres) {
    const SampledMap map = linearMap();
    // World x of cell centre i is -8 + 2i + 1; in between, the map is linear in world units.
    for (float wx = -7.0f; wx <= 7.0f; wx += 0.25f)
        for (float wz = 5.0f; wz <= 19.0f; wz += 0.5f) {
            const float i = (wx + 7.0f) / 2.0f, j = (wz - 5.0f) / 2.0f;
            EXPECT_NEAR(sampleMap(map, wx, wz), 3.0f + 0.5f * i - 0.25f * j, 1e-5f) << wx << ", " << wz;
        }
    EXPECT_EQ(sampleMap(map, -7.0f, 5.0f), map.at(0, 0)); // a cell centre reads the cell, bitwise
    EXPECT_EQ(sampleMap(map, 3.0f, 11.0f), map.at(5, 3));
}

TEST(terrain_MapSample, ClampsAtTheEdgesAndPassesNaN) {
    const SampledMap map = linearMap();
    EXPECT_EQ(sampleMap(map, -1000.0f, 5.0f), map.at(0, 0));
    EXPECT_EQ(sampleMap(map, 1000.0f, 1e30f), map.at(7, 7));
    EXPECT_EQ(sampleMap(map, -std::numeric_limits<float>::infinity(), 19.0f), map.at(0, 7));
    EXPECT_TRUE(std::isnan(sampleMap(map, std::numeric_limits<float>::quiet_NaN(), 0.0f)));
    EXPECT_TRUE(std::isnan(sampleMap(map, 0.0f, std::numeric_limits<float>::quiet_NaN())));
}

TEST(terrain_MapSample, RangeBoundsEverySampleInTheBox) {
    SampledMap map = linearMap();
    for (size_t k = 0; k < map.values.size(); ++k) map.values[k] = std::sin(float(k) * 1.7f) * 40.0f + 7.0f;
    const auto [lo, hi] = std::minmax_element(map.values.begin(), map.values.end());
    map.lowest = *lo, map.highest = *hi;
    for (const auto& [x0, x1, z0, z1] : {std::array{-3.0, 1.0, 6.0, 9.5}, std::array{-20.0, -10.0, 0.0, 30.0},
                                          std::array{2.0, 2.0, 12.0, 12.0}, std::array{-1e9, 1e9, -1e9, 1e9}}) {
        const MapRange range = mapRange(map, x0, x1, z0, z1);
        const double whole = map.highest - map.lowest;
        EXPECT_LE(range.hi - range.lo, whole * 1.001);
        for (double x = x0; x <= x1; x += std::max(0.125, (x1 - x0) / 64))
            for (double z = z0; z <= z1; z += std::max(0.125, (z1 - z0) / 64)) {
                const float h = sampleMap(map, float(x), float(z));
                EXPECT_GE(h, range.lo);
                EXPECT_LE(h, range.hi);
            }
    }
    // A box of a few cells is bounded by those cells, not by the whole map.
    const MapRange near = mapRange(map, -7.0, -7.0, 5.0, 5.0);
    EXPECT_LT(near.hi - near.lo, map.highest - map.lowest);
}

constexpr const char* kTerrain = R"(
world { size = [24, 20, 24]; origin = [-5, -3, 7]; }
terrain hills {
  origin = [-3, 9]; size = 16; levels = [2, 4]; max_height = 12;
  spline crest { points = [[-3, 10, 12], [3, 12, 15], [9, 9, 20], [13, 11, 24]]; radius = 2; }
}
)";

CheckResult checkText(const std::string& text) { return checkSource(SourceFile("map.vox", text)); }

TEST(terrain_MapSample, AFieldSamplesTheMapOncePerColumn) {
    const CheckResult result = checkText(std::string(kTerrain) + R"(
field ground = sdf_heightfield(wp, hills(wx, wz)) < 0 ? 1.0 : 0.0;
pipeline { start; set ground; }
)");
    ASSERT_TRUE(result.program) << result.rendered();
    EXPECT_TRUE(result.diagnostics.empty()) << result.rendered(); // sampled: the terrain counts as used
    const auto mapNode = [](const Program& p) {
        const Field& field = p.fields.at(0);
        return std::find_if(field.nodes.begin(), field.nodes.end(),
                            [](const FieldNode& n) { return n.kind == FieldNode::Kind::Map; });
    };
    const auto declared = mapNode(*result.program);
    ASSERT_NE(declared, result.program->fields.at(0).nodes.end());
    EXPECT_EQ(declared->map->name, "hills");
    EXPECT_EQ(declared->map->size, glm::ivec3(16, 1, 16));
    EXPECT_TRUE(declared->map->values.empty()); // the check generates nothing
    // Unsolved, the map bounds nothing: a chunk's range is unknown rather than made up.
    EXPECT_EQ(mapRange(*declared->map, 0, 1, 0, 1).hi, std::numeric_limits<double>::infinity());
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    EXPECT_EQ(volumeRange(*declared->map, lo, hi).lo, -std::numeric_limits<double>::infinity());
    EXPECT_EQ(volumeRange(*declared->map, lo, hi).hi, std::numeric_limits<double>::infinity());
    Program program = *result.program;
    stages::solveBlocks(program);
    const auto map = mapNode(program);
    EXPECT_EQ(map->map->size, glm::ivec3(16, 1, 16));
    EXPECT_EQ(map->map->values.size(), 16u * 16u);
    const ir::IrModule module = ir::lowerProgram(program, {});
    const ir::IrField& lowered = module.fields.at(0);
    for (size_t i = 0; i < lowered.nodes.size(); ++i)
        if (lowered.nodes[i].kind == FieldNode::Kind::Map) { EXPECT_TRUE(lowered.perColumn.at(i)); }
    // The interpreter's voxels are solid exactly below the sampled height.
    const DenseGrid grid = interpret(program);
    for (int z = 0; z < 24; ++z)
        for (int x = 0; x < 24; ++x) {
            const float h = sampleMap(*map->map, float(x - 5), float(z + 7));
            for (int y = 0; y < 20; ++y) ASSERT_EQ(grid.at({x, y, z}), float(y - 3) - h < 0.0f ? 1.0f : 0.0f);
        }
}

TEST(terrain_MapSample, WrongCallsAreLocatedErrors) {
    struct Case {
        const char* field;
        const char* code;
        const char* message;
    };
    for (const Case& c : {Case{"hills(wx)", "E0006", "takes 2 arguments but 1 was given"},
                          Case{"hills(wp, wz)", "E0010", "argument 1 of 'hills' is vec3"},
                          Case{"hils(wx, wz)", "E0002", "did you mean 'hills'"}}) {
        SCOPED_TRACE(c.field);
        const CheckResult result =
            checkText(std::string(kTerrain) + "field f = " + c.field + ";\npipeline { start; set f; }\n");
        ASSERT_FALSE(result.diagnostics.empty());
        EXPECT_EQ(result.diagnostics.front().code, c.code) << result.rendered();
        EXPECT_NE(result.rendered().find(c.message), std::string::npos) << result.rendered();
        EXPECT_NE(result.rendered().find("map.vox:7:"), std::string::npos) << result.rendered();
    }
}

} // namespace
} // namespace voxc
