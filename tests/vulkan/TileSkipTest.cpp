// Tile skipping (DispatchCursor with a tile shift, tiles.glsl): sweeps run only over the tiles
// where some rule may match, and the result stays bit-identical to the interpreter and to a
// run that dispatches every anchor.
#include "CheckedProgram.h"
#include "Lavapipe.h"
#include "GridCompare.h"
#include "voxc/check/Check.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"

#include <array>
#include <cstring>
#include <glm/common.hpp>
#include <set>
#include <stdexcept>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace voxc {
namespace {

using test::lavapipe;

Program checked(const std::string& text) { return test::checkedProgram("grow.vox", text); }


RunResult run(const Program& program, bool skip, std::array<uint32_t, 3> maxWorkGroups = {0, 0, 0}) {
    ExecutorOptions options;
    options.skipInactiveTiles = skip;
    options.maxWorkGroups = maxWorkGroups;
    VulkanExecutor executor(lavapipe(), compileProgram(program, {}), options);
    return executor.run();
}

const Kernel& kernelNamed(const KernelPackage& package, const std::string& name) {
    for (const Kernel& kernel : package.kernels)
        if (kernel.name == name) return kernel;
    throw std::runtime_error("no kernel " + name);
}

TEST(vulkan_TileSkip, OverhangDispatchesFewTilesAndMatchesTheInterpreter) {
    CheckResult result = checkFile(fmt::format("{}/examples/overhang.vox", VOXC_SOURCE_DIR));
    ASSERT_TRUE(result.program) << result.rendered();
    Program program = std::move(*result.program);
    program.world.chunkSize = 16;
    const RunResult skipping = run(program, true);
    ASSERT_TRUE(skipping.skip.enabled);
    EXPECT_EQ(skipping.skip.tileSize, 8);
    // 6 iterations x 9 phases x the 8^3 tiles of a 64^3 grid holding anchors of the phase.
    EXPECT_GT(skipping.skip.tilePhases, 6u * 9u * 400u);
    // Only the two columns of tiles along the wall face at x = 24 (of eight) can hold a match.
    EXPECT_LT(skipping.skip.activeTilePhases * 3, skipping.skip.tilePhases);
    EXPECT_GT(skipping.skip.activeTilePhases, 0u);
    EXPECT_EQ(test::countBitDifferences(interpret(program), skipping.grid.toDense()), 0u);
    const RunResult direct = run(program, false);
    EXPECT_FALSE(direct.skip.enabled);
    EXPECT_EQ(test::countBitDifferences(direct.grid.toDense(), skipping.grid.toDense()), 0u);
}

// A seed of rock grows into uniform air along +x, -x, +y and +z, crossing many tile and chunk
// borders over the iterations, while a decay rule keeps changing values inside the grown
// region (so tile ranges must widen and be recomputed exactly). Chunk size 8 and a negative
// origin that is not a multiple of it make the tiles straddle the grid's edges.
constexpr const char* kGrowth = R"(
world { size = [37, 21, 19]; origin = [-13, -6, 5]; chunk = 8; seed = 11; }
start {
  fill { value = 0; }
  box { min = [3, 2, 2]; max = [5, 4, 4]; value = 1; }
}
grammar grow {
  iterations = 14;
  clamp = [0, 1];
  rule east { size = [2, 1, 1]; symbol { [GEQ 0.5, LT 0.5] } transform { [NOP, SET 1] } probability = 0.8; }
  rule west { size = [2, 1, 1]; symbol { [LT 0.5, GEQ 0.5] } transform { [SET 0.75, NOP] } probability = 0.6; }
  rule up { size = [1, 2, 1]; symbol { [LT 0.5] [GEQ 0.5] } transform { [SET 1] [NOP] } probability = 0.5; }
  rule north { size = [1, 1, 2]; symbol { layer { [GEQ 0.5] } layer { [LT 0.5] } } transform { layer { [NOP] } layer { [SET 1] } } }
  rule decay { size = [1, 1, 1]; symbol { [GEQ 0.9] } transform { [ADD -0.125] } probability = 0.3; }
}
)";

// The (tile, phase) pairs whose tile holds an anchor of the phase, anchor by anchor.
uint64_t candidateTilePhases(const KernelPackage& package, int tileSize) {
    uint64_t pairs = 0;
    for (const StagePlan& stage : package.stages) {
        if (!stage.grammar) continue;
        for (uint32_t iteration = 0; iteration < stage.grammar->iterations; ++iteration)
            for (const SweepPlan& sweep : stage.grammar->sweeps)
                for (size_t p = 0; p < sweep.phaseStart.size(); ++p) {
                    std::set<std::array<int, 3>> tiles;
                    const glm::ivec3 count = sweep.phaseCount3[p];
                    for (int z = 0; z < count.z; ++z)
                        for (int y = 0; y < count.y; ++y)
                            for (int x = 0; x < count.x; ++x) {
                                const glm::ivec3 anchor = package.world.origin + sweep.phaseStart[p] +
                                                          glm::ivec3(x, y, z) * sweep.phaseStep[p];
                                const glm::ivec3 tile = glm::ivec3(glm::floor(glm::vec3(anchor) / float(tileSize)));
                                tiles.insert({tile.x, tile.y, tile.z});
                            }
                    pairs += tiles.size();
                }
    }
    return pairs;
}

TEST(vulkan_TileSkip, GrowthAcrossTileBordersMatchesTheInterpreter) {
    const Program program = checked(kGrowth);
    const DenseGrid expected = interpret(program);
    const RunResult skipping = run(program, true);
    ASSERT_TRUE(skipping.skip.enabled);
    EXPECT_EQ(skipping.skip.tilePhases, candidateTilePhases(compileProgram(program, {}), skipping.skip.tileSize));
    EXPECT_LT(skipping.skip.activeTilePhases, skipping.skip.tilePhases);
    EXPECT_EQ(test::countBitDifferences(expected, skipping.grid.toDense()), 0u);
    // The rock reached tiles far from the seed.
    EXPECT_GE(expected.at({20, 2, 2}), 0.5f);
    EXPECT_GE(expected.at({3, 2, 15}), 0.5f);
}

// cave_grammar.vox's rules need rock beside air along x in two or three stacked rows: its
// heightfield's surface band meets every density range, but the occupancy bits show the band
// steps at most one voxel at a time, so only tiles at the cliff face stay active.
TEST(vulkan_TileSkip, OccupancyPatternsLeaveOutTheSurfaceBand) {
    CheckResult result = checkFile(fmt::format("{}/examples/cave_grammar.vox", VOXC_SOURCE_DIR));
    ASSERT_TRUE(result.program) << result.rendered();
    const Program program = std::move(*result.program);
    const DenseGrid expected = interpret(program);
    const RunResult skipping = run(program, true);
    ASSERT_TRUE(skipping.skip.enabled);
    EXPECT_EQ(skipping.skip.tileSize, 8);
    // Density ranges alone keep about 16% of the tile-phases (the surface band and the face).
    EXPECT_LT(skipping.skip.activeTilePhases * 20, skipping.skip.tilePhases);
    EXPECT_GT(skipping.skip.activeTilePhases, 0u);
    EXPECT_EQ(test::countBitDifferences(expected, skipping.grid.toDense()), 0u);
    // Fewer workgroups make the runtime choose tiles of 16 (occupancy bits kept) and of 32 (too
    // wide for a row of bits: ranges alone); both give the same voxels.
    const RunResult tiles16 = run(program, true, {64, 64, 65535});
    EXPECT_EQ(tiles16.skip.tileSize, 16);
    EXPECT_LT(tiles16.skip.activeTilePhases * 4, tiles16.skip.tilePhases);
    EXPECT_EQ(test::countBitDifferences(expected, tiles16.grid.toDense()), 0u);
    const RunResult tiles32 = run(program, true, {512, 8, 65535});
    EXPECT_EQ(tiles32.skip.tileSize, 32);
    EXPECT_EQ(test::countBitDifferences(expected, tiles32.grid.toDense()), 0u);
}

// The level is the test that decides the most cells: here `> 0.25` (three cells of `GT 0.25`
// and one of `LEQ 0.25` against one `GEQ 0.5`). A cell that passes NaN (NEQ) or both sides
// of the level is left to the ranges.
TEST(vulkan_TileSkip, OccupancyLevelDecidesTheMostCells) {
    const Program program = checked(R"(
world { size = [24, 20, 16]; chunk = 8; seed = 5; }
start {
  fill { value = 0; }
  box { min = [0, 0, 0]; max = [10, 12, 16]; value = 0.75; }
  box { min = [4, 0, 0]; max = [14, 6, 16]; value = 0.2; }
}
grammar levels {
  iterations = 3;
  clamp = [0, 1];
  rule edge { size = [3, 1, 1]; symbol { [GT 0.25, GT 0.25, LEQ 0.25] } transform { [NOP, NOP, ADD 0.125] } }
  rule other { size = [3, 1, 1]; symbol { [NEQ 0.3, GT 0.25, GEQ 0.5] } transform { [NOP, ADD -0.25, NOP] } }
}
)");
    const KernelPackage package = compileProgram(program, {});
    EXPECT_NE(kernelNamed(package, "tile_ranges").glsl.find("bool occupied(float density) { return density > 0.25; }"),
              std::string::npos);
    const std::string& tiles = kernelNamed(package, "levels_sweep0_active_tiles").glsl;
    EXPECT_NE(tiles.find("(anchorsX & (row_0_0 >> 0) & (row_0_0 >> 1) & (~row_0_0 >> 2)) != 0u); // edge"),
              std::string::npos)
        << tiles;
    EXPECT_NE(tiles.find("(anchorsX & (row_0_0 >> 1) & (row_0_0 >> 2)) != 0u); // other"), std::string::npos);
    const RunResult skipping = run(program, true);
    EXPECT_EQ(test::countBitDifferences(interpret(program), skipping.grid.toDense()), 0u);
    EXPECT_LT(skipping.skip.activeTilePhases, skipping.skip.tilePhases);
}

TEST(vulkan_TileSkip, ValidationLayerReportsNothing) {
    VulkanContext context(ContextOptions{.device = "lavapipe", .validation = true});
    VulkanExecutor executor(context, compileProgram(checked(kGrowth), {}));
    EXPECT_TRUE(executor.run().skip.enabled);
    for (const ValidationMessage& message : context.validationMessages()) ADD_FAILURE() << message.text;
}

} // namespace
} // namespace voxc
