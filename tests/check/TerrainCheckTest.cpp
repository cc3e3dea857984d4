// terrain blocks: the host generator's height map voxelised into a solve table whose 0.5
// surface lies at the height, with the block's materials; erosion moves ground and says so. The
// check keeps the block unsolved; the run's solve (stages::solveBlocks) makes the table.
#include "CheckTestUtil.h"

#include "voxc/stages/Solve.h"

#include <gtest/gtest.h>

namespace voxc {
namespace terrain_check_test {

const std::string kWorld = "world { size = [64, 32, 64]; }\nmaterial rock { id = 1; }\nmaterial sand { id = 2; }\n";

// A plateau: one spline whose flat band covers the middle of the map at height 20.
const std::string kPlateau = R"(
terrain land {
  max_height = 32;
  levels = [2, 6];
  material = rock;
  spline top { points = [[0, 20, 32], [20, 20, 32], [44, 20, 32], [64, 20, 32]]; radius = 12; left = [16, -8]; right = [16, -8]; }
}
pipeline { start; set land; }
)";

// The block's table, solved from a copy of the checked program (the check made none).
SolveTable tableOf(const CheckResult& result) {
    EXPECT_TRUE(result.program && !result.hasErrors()) << result.rendered();
    EXPECT_EQ(result.program->curves.size(), 1u);
    EXPECT_EQ(result.program->curves.at(0).table, nullptr);
    Program program = *result.program;
    stages::solveBlocks(program);
    return program.curves.at(0).solved();
}

TEST(check_Terrain, ThePlateauSurfaceLiesAtItsHeight) {
    const CheckResult result = test::check(kWorld + kPlateau);
    const SolveTable table = tableOf(result);
    ASSERT_EQ(table.size, glm::ivec3(64, 32, 64));
    EXPECT_EQ(table.source, "terrain");
    const auto at = [&](int x, int y, int z) { return size_t(x) + 64 * (size_t(y) + 32 * size_t(z)); };
    // On the spline: density (20 - y) / ramp + 0.5 with the default ramp of 2.
    EXPECT_NEAR(table.density[at(32, 20, 32)], 0.5f, 1e-4f);
    EXPECT_NEAR(table.density[at(32, 19, 32)], 1.0f, 1e-4f);
    EXPECT_NEAR(table.density[at(32, 21, 32)], 0.0f, 1e-4f);
    EXPECT_EQ(table.material[at(32, 10, 32)], 1);  // solid: the block's material
    EXPECT_EQ(table.material[at(32, 25, 32)], 0);  // air: none
    // Every column falls from rock to air exactly once.
    for (int z = 0; z < 64; z += 7)
        for (int x = 0; x < 64; x += 7)
            for (int y = 1; y < 32; ++y) EXPECT_LE(table.density[at(x, y, z)], table.density[at(x, y - 1, z)]);
}

TEST(check_Terrain, ErosionMovesGroundAndDepositsGetTheirMaterial) {
    std::string eroded = kPlateau;
    eroded.replace(eroded.find("material = rock;"), 16,
                   "material = rock; preset = mountain_river; steps_scale = 0.1; deposit_material = sand; "
                   "deposit_threshold = 0.01;");
    const CheckResult result = test::check(kWorld + eroded);
    const SolveTable table = tableOf(result);
    EXPECT_NE(table.notes.find("erosion steps"), std::string::npos) << table.notes;
    EXPECT_EQ(table.notes.find(" 0 erosion steps"), std::string::npos) << table.notes;
    const CheckResult plain = test::check(kWorld + kPlateau);
    EXPECT_NE(tableOf(plain).density, table.density);
    EXPECT_NE(std::count(table.material.begin(), table.material.end(), uint8_t(2)), 0);
}

TEST(check_Terrain, SameFileSameTable) {
    const CheckResult a = test::check(kWorld + kPlateau), b = test::check(kWorld + kPlateau);
    EXPECT_EQ(tableOf(a).density, tableOf(b).density);
}

} // namespace terrain_check_test
} // namespace voxc

namespace voxc {
namespace terrain_check_test {

// The surface height of column (x, z): the lowest y whose density is below 0.5.
int surfaceAt(const SolveTable& table, int x, int z) {
    for (int y = 0; y < table.size.y; ++y)
        if (table.density[size_t(x) + size_t(table.size.x) * (size_t(y) + size_t(table.size.y) * size_t(z))] < 0.5f)
            return y;
    return table.size.y;
}

TEST(check_Terrain, MetaPointsVaryASplineAlongIt) {
    // The flat band is 12 wide at the spline's start and 0 at its end: 6 to 10 voxels off the
    // axis the ground is held at the band's height near the start and sinks (diffused, the side
    // gradients are soft; docs/terrain.md) near the end.
    const std::string text = kWorld + R"(
terrain land {
  max_height = 32;
  levels = [2, 6];
  spline top {
    points = [[0, 20, 32], [20, 20, 32], [44, 20, 32], [64, 20, 32]];
    left = [16, -8]; right = [16, -8];
    meta { at = 0; radius = 12; }
    meta { at = 1; radius = 0; }
  }
}
pipeline { start; set land; }
)";
    const CheckResult result = test::check(text);
    const SolveTable table = tableOf(result);
    const CheckResult constant = test::check(kWorld + kPlateau); // radius 12 all along
    for (int z : {38, 40, 42}) {
        EXPECT_GT(surfaceAt(table, 6, z), surfaceAt(table, 58, z)) << z;
        EXPECT_EQ(surfaceAt(tableOf(constant), 6, z), surfaceAt(tableOf(constant), 58, z)) << z;
    }
}

TEST(check_Terrain, MetaPointErrorsAreLocated) {
    const auto splineWith = [](const std::string& metas) {
        return kWorld + "terrain land { max_height = 32; levels = [2, 5];\n"
                        "  spline s { points = [[0, 20, 32], [20, 20, 32], [44, 20, 32], [64, 20, 32]];\n" +
               metas + "\n  }\n}\npipeline { start; set land; }\n";
    };
    EXPECT_EQ(test::codes(test::check(splineWith("meta { at = 1; } meta { at = 0.5; }"))),
              std::vector<std::string>{"E0007"}); // not ascending
    EXPECT_EQ(test::codes(test::check(splineWith("meta { at = 2; }"))), std::vector<std::string>{"E0007"}); // past C
    EXPECT_EQ(test::codes(test::check(splineWith("meta { radius = 3; }"))), std::vector<std::string>{"E0009"});
    EXPECT_EQ(test::codes(test::check(splineWith("knot { at = 0; }"))), std::vector<std::string>{"E0008"});
}

} // namespace terrain_check_test
} // namespace voxc
