// terrain blocks: the host generator's height map voxelised into a solve table whose 0.5
// surface lies at the height, with the block's materials; erosion moves ground and says so.
#include "CheckTestUtil.h"

#include <gtest/gtest.h>

namespace voxc {
namespace {

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

const SolveTable& tableOf(const CheckResult& result) {
    EXPECT_TRUE(result.program && !result.hasErrors()) << result.rendered();
    EXPECT_EQ(result.program->curves.size(), 1u);
    return *result.program->curves.at(0).table;
}

TEST(check_Terrain, ThePlateauSurfaceLiesAtItsHeight) {
    const CheckResult result = test::check(kWorld + kPlateau);
    const SolveTable& table = tableOf(result);
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
    const SolveTable& table = tableOf(result);
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

} // namespace
} // namespace voxc
