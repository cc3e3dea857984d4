// Stamps (docs/language.md, "Stamps"): a firing rule combines a field, placed in its window's
// frame, into the window grown by its reach. Checked against a hand-applied stamp, for
// overlapping stamps of one phase crossing chunk borders on Vulkan at chunk sizes 8, 16 and 32
// and odd origins (bit for bit the interpreter's), for a turned variant, and for a region, whose
// halo must hold the reach.
#include "CheckedProgram.h"
#include "GridCompare.h"
#include "Lavapipe.h"
#include "voxc/check/Check.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/program/Semantics.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Region.h"

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>
#include <gtest/gtest.h>

namespace voxc {
namespace {

Program checked(const std::string& text) { return test::checkedProgram("stamps.vox", text); }

// Boulders (union, sandstone) and pits (subtract) stamped on a noisy ground by rules of one
// [2, 1, 1] sweep at stride 1: a phase's anchors are 2 voxels apart along x, so the grown
// windows (reach 3) of one phase overlap, and both rules fire in one phase.
std::string overlapping(glm::ivec3 origin, int chunk) {
    return fmt::format(R"(
world {{ size = [37, 22, 29]; origin = [{}, {}, {}]; chunk = {}; seed = 5; }}
material rock {{ id = 1; color = [0.5, 0.5, 0.5]; }}
material sandstone {{ id = 2; color = [0.8, 0.6, 0.4]; }}
start {{
  fill {{ value = 0; }}
  heightfield {{ base = 9; amplitude = 5; frequency = 0.09; octaves = 2; material = rock; }}
}}
field boulder = density(sdf_sphere(p, vec3(0.5, 1, 0), 2.2 + 0.5 * perlin3(wp * 0.3, 4)), 1.5);
field pit = density(sdf_box(p, vec3(0.5, 0, 0.3), vec3(1.5, 2, 2.5)), 1);
grammar stamps {{
  iterations = 2;
  rule rest_boulder {{
    size = [2, 1, 1];
    probability = 0.08;
    symbol {{ [PRES, ABS] }}
    transform {{ [NOP, NOP] }}
    stamp boulder {{ mode = union; reach = 3; material = sandstone; }}
  }}
  rule dig_pit {{
    size = [2, 1, 1];
    probability = 0.05;
    symbol {{ [ABS, PRES] }}
    transform {{ [NOP, SET 0.25] }}
    stamp pit {{ mode = subtract; offset = [0, 1, 0]; reach = [2, 3, 3]; }}
  }}
}}
pipeline {{ start; stamps; }}
)",
                       origin.x, origin.y, origin.z, chunk);
}

TEST(e2e_Stamps, OverlappingStampsAgreeOnVulkanAtEveryChunkSize) {
    const DenseGrid reference = interpret(checked(overlapping({-5, 3, 7}, 16)));
    // The stamps did something: sandstone boulders stand on the ground.
    size_t sandstone = 0;
    for (uint8_t m : reference.materials()) sandstone += m == 2;
    EXPECT_GT(sandstone, 100u);
    for (const glm::ivec3 origin : {glm::ivec3(-5, 3, 7), glm::ivec3(13, -9, -21)})
        for (const int chunk : {8, 16, 32}) {
            SCOPED_TRACE(fmt::format("origin ({}, {}, {}), chunk {}", origin.x, origin.y, origin.z, chunk));
            const Program program = checked(overlapping(origin, chunk));
            const DenseGrid interpreted = interpret(program);
            if (origin == glm::ivec3(-5, 3, 7)) { EXPECT_EQ(test::countBitDifferences(reference, interpreted), 0u); }
            EXPECT_EQ(test::countBitDifferences(interpreted, test::runOnLavapipe(program)), 0u);
            EXPECT_EQ(test::countBitDifferences(interpreted,
                                                test::runOnLavapipe(program, {.skipInactiveTiles = false})),
                      0u);
        }
}

// One window matches (the only sandstone voxel); its stamp is a box far larger than the reach,
// so exactly the grown window [anchor - reach, anchor + window + reach) turns solid, clipped to
// the grid, and the material goes where the box won.
TEST(e2e_Stamps, OneStampWritesExactlyItsGrownWindow) {
    const Program program = checked(R"(
world { size = [20, 12, 16]; origin = [3, 0, -2]; chunk = 8; }
material sandstone { id = 2; color = [0.8, 0.6, 0.4]; }
start { fill { value = 0; } box { min = [15, 2, 3]; max = [16, 3, 4]; value = 0.25; material = sandstone; } }
field slab = 1;
grammar g {
  rule here {
    size = [2, 1, 1];
    symbol { [MAT sandstone, ABS] }
    transform { [NOP, NOP] }
    stamp slab { mode = union; reach = [4, 1, 2]; material = sandstone; }
  }
}
pipeline { start; g; }
)");
    const DenseGrid grid = interpret(program);
    const glm::ivec3 anchor(15, 2, 3), lo = anchor - glm::ivec3(4, 1, 2), hi = glm::min(anchor + glm::ivec3(2, 1, 1) + glm::ivec3(4, 1, 2), grid.size());
    for (int z = 0; z < grid.size().z; ++z)
        for (int y = 0; y < grid.size().y; ++y)
            for (int x = 0; x < grid.size().x; ++x) {
                const glm::ivec3 v(x, y, z);
                const bool inside = glm::all(glm::greaterThanEqual(v, lo)) && glm::all(glm::lessThan(v, hi));
                ASSERT_EQ(grid.at(v), inside ? 1.0f : 0.0f) << x << " " << y << " " << z;
                ASSERT_EQ(grid.materialAt(v), inside ? 2 : 0) << x << " " << y << " " << z;
            }
    EXPECT_EQ(test::countBitDifferences(grid, test::runOnLavapipe(program)), 0u);
}

// A stamp written for +x turns with its variant: under `symmetry = rot_y` the rule finds a step
// facing each way and puts its (asymmetric) wedge in front of it.
TEST(e2e_Stamps, VariantsTurnTheirStamps) {
    const std::string text = R"(
world { size = [30, 14, 30]; origin = [-1, 0, 5]; chunk = 16; seed = 2; }
start { fill { value = 0; } box { min = [0, 0, 0]; max = [30, 4, 30]; } box { min = [10, 4, 10]; max = [20, 8, 20]; } }
field wedge = density(sdf_box(p, vec3(3, 1, 0), vec3(3, 1, 1)), 1);
grammar g {
  symmetry = rot_y;
  rule ledge {
    size = [2, 1, 1];
    probability = 0.5;
    symbol { [PRES, ABS] }
    transform { [NOP, NOP] }
    stamp wedge { reach = [6, 2, 2]; }
  }
}
pipeline { start; g; }
)";
    const Program program = checked(text);
    EXPECT_EQ(program.grammars[0].rules.size(), 4u);
    const DenseGrid start = evaluateStart(program);
    const DenseGrid grid = interpret(program);
    // Wedges grew out of all four walls of the block at y = 4.
    const auto grew = [&](glm::ivec3 v) { return start.at(v) == 0.0f && grid.at(v) > 0.0f; };
    int east = 0, west = 0, north = 0, south = 0;
    for (int i = 10; i < 20; ++i) {
        east += grew({21, 4, i}), west += grew({8, 4, i}), north += grew({i, 4, 21}), south += grew({i, 4, 8});
    }
    EXPECT_GT(east, 0);
    EXPECT_GT(west, 0);
    EXPECT_GT(north, 0);
    EXPECT_GT(south, 0);
    EXPECT_EQ(test::countBitDifferences(grid, test::runOnLavapipe(program)), 0u);
}

// A region of the world equals the whole run's voxels there: the halo holds the stamps' reach
// (the grammar cone grows by it each phase).
TEST(e2e_Stamps, RegionHaloHoldsTheReach) {
    const Program whole = checked(overlapping({-5, 3, 7}, 8));
    const DenseGrid full = interpret(whole);
    const stages::GridBox region{{11, 4, 9}, {19, 13, 17}};
    const stages::PipelineHalo halo = stages::pipelineHalo(whole);
    EXPECT_GE(halo.radius.x, 3 + 2); // at least one phase's reach plus the window
    const stages::GridBox box = stages::haloBox(whole, region, halo.radius);
    const DenseGrid part = interpret(stages::regionProgram(whole, box));
    const stages::GridBox inPart{region.min - box.min, region.max - box.min};
    EXPECT_EQ(test::countBitDifferences(stages::cropGrid(full, region), stages::cropGrid(part, inPart)), 0u);
}

} // namespace
} // namespace voxc
