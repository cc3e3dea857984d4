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

#include <chrono>
#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>
#include <gtest/gtest.h>

namespace voxc {
namespace stamps_test {

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

size_t changedVoxels(const DenseGrid& before, const DenseGrid& after) {
    size_t changed = 0;
    for (size_t i = 0; i < before.data().size(); ++i) changed += before.data()[i] != after.data()[i];
    return changed;
}

// A small L-system network stamped at every window where a rock face meets air, turned toward
// each side by `symmetry = rot_y`: its turtle starts at the anchor + offset and digs into the
// rock in the written rule's +x, whichever way the face looks.
std::string lsystemStamp(glm::ivec3 origin, int chunk) {
    return fmt::format(R"(
world {{ size = [44, 20, 40]; origin = [{}, {}, {}]; chunk = {}; seed = 3; }}
material rock {{ id = 1; color = [0.5, 0.5, 0.5]; }}
start {{
  fill {{ value = 0; }}
  box {{ min = [9, 0, 8]; max = [35, 14, 32]; material = rock; }}
}}
lsystem burrow {{
  axiom = "FF[RF][LF]";
  expansions = 0;
  step = 3;
}}
feature burrows = lsystem_cave {{ lsystem = burrow; radius = 2; clearance = 1; curl_amplitude = 1; min_scale = 1; }}
grammar dig {{
  bounds = [[0, 6, 0], [44, 7, 40]];
  stride = [1, 1, 4];
  symmetry = rot_y;
  rule face {{
    size = [2, 1, 1];
    probability = 0.5;
    symbol {{ [ABS, PRES] }}
    transform {{ [NOP, NOP] }}
    stamp burrows {{ mode = subtract; offset = [1, 0, 0]; reach = [14, 6, 8]; }}
  }}
}}
pipeline {{ start; dig; }}
)",
                       origin.x, origin.y, origin.z, chunk);
}

TEST(e2e_Stamps, LsystemCaveStampsAgreeOnVulkanAtEveryChunkSize) {
    const Program program = checked(lsystemStamp({-7, 5, 11}, 16));
    const DenseGrid start = evaluateStart(program);
    const DenseGrid grid = interpret(program);
    // Burrows were dug into all four faces of the block, each beginning at its face.
    int east = 0, west = 0, north = 0, south = 0;
    for (int i = 10; i < 34; ++i) {
        west += grid.at({11, 6, i}) < 0.5f, east += grid.at({32, 6, i}) < 0.5f;
        south += grid.at({i, 6, 10}) < 0.5f, north += grid.at({i, 6, 29}) < 0.5f;
    }
    EXPECT_GT(west, 0);
    EXPECT_GT(east, 0);
    EXPECT_GT(south, 0);
    EXPECT_GT(north, 0);
    EXPECT_GT(changedVoxels(start, grid), 200u);
    test::expectLavapipeMatchesAtEveryChunkSize(program, grid);
    // At another origin the world coordinates (and so the brush's noise and the rule draws) change;
    // the interpreter is the reference there too.
    const Program moved = checked(lsystemStamp({13, -9, -21}, 8));
    test::expectLavapipeMatchesAtEveryChunkSize(moved, interpret(moved));
}

// Symmetry variants share their stamps' code (codegen/StampKernel.cpp: the variant's axes come
// from a table indexed by the fired rule), so the stamp kernel under `symmetry = all` (48
// elements; here 32 live variants) is no bigger than under none but for one table entry per
// rule, and the driver compiles it within a generous multiple of none's time (it took minutes when
// every variant had its own copy of the carve); the result still matches the interpreter.
TEST(e2e_Stamps, StampKernelsDoNotGrowWithSymmetryVariants) {
    const auto withSymmetry = [](const std::string& symmetry) {
        std::string text = lsystemStamp({0, 0, 0}, 16);
        const size_t at = text.find("symmetry = rot_y;");
        text.replace(at, std::string("symmetry = rot_y;").size(), symmetry);
        return checked(text);
    };
    const Program none = withSymmetry(""), all = withSymmetry("symmetry = all;");
    const auto stampKernel = [](const KernelPackage& package) {
        const Kernel* found = nullptr;
        for (const Kernel& kernel : package.kernels)
            if (kernel.glsl.find("stampWrittenCell(fromAnchor") != std::string::npos) found = &kernel;
        EXPECT_NE(found, nullptr);
        return found ? found->glsl.size() : 0;
    };
    const KernelPackage nonePackage = compileProgram(none, {}), allPackage = compileProgram(all, {});
    const size_t noneSize = stampKernel(nonePackage), allSize = stampKernel(allPackage);
    EXPECT_LT(double(allSize), 1.25 * double(noneSize)) << noneSize << " vs " << allSize;
    // Pipelines are created (the driver compiles) when the executor is made; the stated bound is
    // 6x none's time, plus a second for a loaded machine.
    const auto compileSeconds = [](const KernelPackage& package) {
        const auto begin = std::chrono::steady_clock::now();
        VulkanExecutor executor(test::lavapipe(), package, {});
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    };
    const double noneSeconds = compileSeconds(nonePackage), allSeconds = compileSeconds(allPackage);
    EXPECT_LT(allSeconds, 6.0 * noneSeconds + 1.0) << noneSeconds << " s vs " << allSeconds << " s";
    test::expectLavapipeMatchesAtEveryChunkSize(all, interpret(all));
}

// The stamped network is the lsystem's, moved to start at the anchor + offset: one firing (the
// only sandstone voxel) carves exactly what the same lsystem_cave carves as a pipeline stage whose
// turtle starts there. The network is drawn on whole voxels (right angles, whole steps, no curl
// displacement), so moving it changes no float, and the brush's noise reads the world place in both.
TEST(e2e_Stamps, LsystemCaveStampIsTheCarveMovedToTheAnchor) {
    const auto program = [](const std::string& stamp, const std::string& pipeline) {
        return checked(fmt::format(R"(
world {{ size = [40, 20, 30]; origin = [2, -3, 5]; chunk = 8; seed = 9; }}
material sandstone {{ id = 2; color = [0.8, 0.6, 0.4]; }}
start {{ fill {{ value = 1; }} box {{ min = [6, 9, 14]; max = [7, 10, 15]; value = 0.75; material = sandstone; }} }}
lsystem burrow {{ axiom = "FFF[RFF]F[LF]"; expansions = 0; angle = 90; step = 3; start = [10, 7, 18]; }}
feature burrows = lsystem_cave {{ lsystem = burrow; radius = 2.5; clearance = 1; curl_amplitude = 0; min_scale = 1; }}
grammar dig {{
  bounds = [[6, 9, 14], [7, 10, 15]];
  rule here {{
    size = [1, 1, 1];
    symbol {{ [MAT sandstone] }}
    transform {{ [SET 1] }}
    {}
  }}
}}
pipeline {{ start; dig; {} }}
)",
                                   stamp, pipeline));
    };
    // The anchor is grid voxel (6, 9, 14), so the frame's origin is grid (8, 10, 13), world
    // (10, 7, 18), where the pipeline carve's turtle starts (its start is in world coordinates).
    const Program stamped = program("stamp burrows { mode = subtract; offset = [2, 1, -1]; reach = [26, 10, 12]; }", "");
    const Program carved = program("", "subtract burrows;");
    const DenseGrid stampedGrid = interpret(stamped);
    EXPECT_EQ(test::countBitDifferences(stampedGrid, interpret(carved)), 0u);
    EXPECT_GT(changedVoxels(evaluateStart(stamped), stampedGrid), 100u);
    EXPECT_EQ(test::countBitDifferences(stampedGrid, test::runOnLavapipe(stamped)), 0u);
}

} // namespace stamps_test
} // namespace voxc
