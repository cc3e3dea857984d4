// A region run on lavapipe (its region program compiled to kernels and run by the executor) equals
// the same box of the interpreter's whole world, at chunk sizes 8, 16 and 32, with the world at
// negative coordinates and the box straddling chunks: the start and field kernels add
// World::localBase, the sweeps keep the declared phases, the curves kernel reads its cropped table.
#include "GridCompare.h"
#include "Lavapipe.h"
#include "voxc/check/Check.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Region.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace voxc {
namespace {

class RegionOnLavapipe : public ::testing::TestWithParam<std::string> {};

TEST_P(RegionOnLavapipe, EqualsTheInterpretersWholeWorld) {
    CheckResult checked = checkFile(fmt::format("{}/examples/{}.vox", VOXC_SOURCE_DIR, GetParam()));
    ASSERT_FALSE(checked.hasErrors()) << checked.rendered();
    Program program = std::move(*checked.program);
    program.world.origin += glm::ivec3(-37, -5, -21);
    const DenseGrid whole = interpret(program);
    const glm::ivec3 size = program.world.size;
    const stages::GridBox region{glm::ivec3(5, 3, 9), glm::ivec3(size.x / 2 + 7, size.y - 4, size.z / 2 + 11)};
    const stages::GridBox computed = stages::haloBox(program, region, stages::pipelineHalo(program).radius);
    for (int chunk : {8, 16, 32}) {
        SCOPED_TRACE(fmt::format("chunk {}", chunk));
        program.world.chunkSize = chunk;
        const DenseGrid grid = test::runOnLavapipe(stages::regionProgram(program, computed));
        const DenseGrid actual = stages::cropGrid(grid, {region.min - computed.min, region.max - computed.min});
        EXPECT_EQ(test::countVoxelDifferences(stages::cropGrid(whole, region), actual), 0u);
    }
}

INSTANTIATE_TEST_SUITE_P(examples, RegionOnLavapipe, ::testing::Values("scene", "curves_cliff", "speleothems"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

} // namespace
} // namespace voxc
