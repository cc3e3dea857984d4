// The material channel on Vulkan against the interpreter, id for id, on hand-built programs
// (tests/ir/support/SamplePrograms.h) that read and write materials every way the language can:
// at chunk sizes 8, 16 and 32, at shifted origins, through the staging path and without tile
// skipping.
#include "Lavapipe.h"
#include "GridCompare.h"
#include "SamplePrograms.h"
#include "voxc/check/Check.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <set>

namespace voxc {
namespace materials_test {

using test::lavapipe;

std::set<int> materialsIn(const DenseGrid& grid) {
    return std::set<int>(grid.materials().begin(), grid.materials().end());
}

class MaterialsOnVulkan : public ::testing::TestWithParam<bool> {};

TEST_P(MaterialsOnVulkan, MatchInterpreterAtEveryChunkSizeAndOrigin) {
    Program program = test::materialProgram(GetParam());
    for (glm::ivec3 shift : {glm::ivec3(0), glm::ivec3(-37, -5, -100), glm::ivec3(100003, 7, -65541)}) {
        Program shifted = program;
        shifted.world.origin += shift;
        const DenseGrid expected = interpret(shifted);
        // The program exercises the channel: none, rock, sand and moss all survive somewhere.
        EXPECT_EQ(materialsIn(expected), (std::set<int>{0, 1, 2, 3}));
        for (int chunk : {8, 16, 32}) {
            SCOPED_TRACE(fmt::format("origin shift ({}, {}, {}), chunk {}", shift.x, shift.y, shift.z, chunk));
            shifted.world.chunkSize = chunk;
            EXPECT_EQ(test::countVoxelDifferences(expected, test::runOnLavapipe(shifted)), 0u);
        }
    }
}

TEST_P(MaterialsOnVulkan, StagedAndUnskippedRunsMatch) {
    const Program program = test::materialProgram(GetParam());
    const DenseGrid expected = interpret(program);
    ExecutorOptions staged;
    staged.alwaysStage = true;
    EXPECT_EQ(test::countVoxelDifferences(expected, test::runOnLavapipe(program, staged)), 0u);
    ExecutorOptions unskipped;
    unskipped.skipInactiveTiles = false;
    EXPECT_EQ(test::countVoxelDifferences(expected, test::runOnLavapipe(program, unskipped)), 0u);
}

INSTANTIATE_TEST_SUITE_P(e2e, MaterialsOnVulkan, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "WithSet" : "EveryMode"; });

// The validation layer sees the material buffer bound, cleared, written and read back (mapped
// and staged) without a message; the runs skip tiles, so the material tests meet skipping.
TEST(e2e_Materials, ValidationLayerReportsNothing) {
    VulkanContext context(ContextOptions{.device = "lavapipe", .validation = true});
    const Program program = test::materialProgram(false);
    const DenseGrid expected = interpret(program);
    const KernelPackage package = compileProgram(program, {});
    for (const bool staged : {false, true}) {
        ExecutorOptions options;
        options.alwaysStage = staged;
        options.dispatchesPerBatch = 3;
        VulkanExecutor executor(context, package, options);
        const RunResult result = executor.run();
        EXPECT_TRUE(result.skip.enabled);
        EXPECT_LT(result.skip.activeTilePhases, result.skip.tilePhases);
        EXPECT_EQ(test::countVoxelDifferences(expected, result.grid.toDense()), 0u);
    }
    for (const ValidationMessage& m : context.validationMessages())
        ADD_FAILURE() << (m.error ? "validation error: " : "validation warning: ") << m.text;
}

// The .vox material cases that InterpVsVulkan compares do exercise the channel.
TEST(e2e_Materials, MaterialCasesWriteSeveralMaterials) {
    for (const char* name : {"materials_grammar", "materials_fields"}) {
        SCOPED_TRACE(name);
        CheckResult checked = checkFile(fmt::format("{}/tests/e2e/cases/{}.vox", VOXC_SOURCE_DIR, name));
        ASSERT_TRUE(checked.program) << checked.rendered();
        EXPECT_TRUE(checked.program->usesMaterials());
        EXPECT_GE(materialsIn(interpret(*checked.program)).size(), 3u);
    }
}

// A program without materials reads back every voxel as `none` (its kernels declare no buffer).
TEST(e2e_Materials, ProgramWithoutMaterialsReadsBackNone) {
    Program program = test::sampleProgram();
    ASSERT_FALSE(program.usesMaterials());
    const DenseGrid actual = test::runOnLavapipe(program);
    EXPECT_EQ(materialsIn(actual), std::set<int>{0});
    EXPECT_EQ(test::countVoxelDifferences(interpret(program), actual), 0u);
}

// Run twice on one executor: the second run starts from cleared materials again.
TEST(e2e_Materials, RepeatedRunsClearMaterials) {
    const Program program = test::materialProgram(false);
    VulkanExecutor executor(lavapipe(), compileProgram(program, {}));
    const DenseGrid first = executor.run().grid.toDense();
    const DenseGrid second = executor.run().grid.toDense();
    EXPECT_EQ(test::countVoxelDifferences(first, second), 0u);
}

} // namespace materials_test
} // namespace voxc
