// Every example, whole and as regions: a region run on its own (its box grown by the pipeline's
// halo, run as a grid of its own, cropped) equals the same box of the whole world's run, densities
// bit for bit and materials id for id, for boxes at odd offsets, touching the world's faces,
// straddling chunk borders and one voxel wide, with the world moved to negative coordinates
// (RegionLavapipeTest runs the kernels' side at chunk sizes 8, 16 and 32).
#include "GridCompare.h"
#include "voxc/check/Check.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Region.h"

#include <fmt/format.h>
#include <glm/common.hpp>
#include <fstream>
#include <glm/vector_relational.hpp>
#include <gtest/gtest.h>
#include <iterator>

namespace voxc {
namespace {

Program loadExample(const std::string& name) {
    CheckResult result = checkFile(fmt::format("{}/examples/{}.vox", VOXC_SOURCE_DIR, name));
    EXPECT_FALSE(result.hasErrors()) << result.rendered();
    return std::move(*result.program);
}

// The box's voxels, by the interpreter, through a region program.
DenseGrid interpretRegion(const Program& program, const stages::GridBox& region) {
    const stages::GridBox computed = stages::haloBox(program, region, stages::pipelineHalo(program).radius);
    const DenseGrid grid = interpret(stages::regionProgram(program, computed));
    return stages::cropGrid(grid, {region.min - computed.min, region.max - computed.min});
}

// Boxes of a world of `size`: odd offsets, each face of the world, chunk borders (multiples of 8
// to 32 from the origin) crossed, and a single voxel.
std::vector<stages::GridBox> regionsOf(glm::ivec3 size) {
    const auto clip = [&](glm::ivec3 lo, glm::ivec3 hi) {
        lo = glm::clamp(lo, glm::ivec3(0), size - 1);
        return stages::GridBox{lo, glm::clamp(hi, lo + 1, size)};
    };
    return {clip({3, 5, 7}, {3 + size.x / 3, size.y - 2, 7 + size.z / 2}),
            clip(size - glm::ivec3(13, 9, 11), size),
            clip({0, 0, 0}, {17, size.y / 2 + 1, 9}),
            clip(size / 2 - glm::ivec3(7), size / 2 + glm::ivec3(9)),
            clip(size / 2 + glm::ivec3(1, -3, 2), size / 2 + glm::ivec3(2, -2, 3))};
}

class RegionOfExample : public ::testing::TestWithParam<std::string> {};

TEST_P(RegionOfExample, EqualsTheWholeWorldThere) {
    Program program = loadExample(GetParam());
    for (const glm::ivec3 shift : {glm::ivec3(-45, -7, -19)}) {
        Program moved = program;
        moved.world.origin += shift;
        const DenseGrid whole = interpret(moved);
        std::vector<stages::GridBox> regions = regionsOf(moved.world.size);
        // caves.vox interprets for half a minute per grid: the chunk-straddling box and the single voxel.
        if (GetParam() == "caves") regions = {regions[3], regions[4]};
        for (const stages::GridBox& region : regions) {
            SCOPED_TRACE(fmt::format("origin ({}, {}, {}), box ({}, {}, {})..({}, {}, {})", moved.world.origin.x,
                                     moved.world.origin.y, moved.world.origin.z, region.min.x, region.min.y,
                                     region.min.z, region.max.x, region.max.y, region.max.z));
            EXPECT_EQ(test::countVoxelDifferences(stages::cropGrid(whole, region), interpretRegion(moved, region)), 0u);
        }
    }
}

// A world far larger than one grid: scene.vox at 4096 x 64 x 4096 (a whole run is over the grid
// limit) checks for a region, whose voxels equal the declared 96 x 64 x 96 world's there (the box
// and its halo lie inside the small world, away from its border, so both worlds agree on them).
TEST(RegionOfALargeWorld, EqualsTheSmallWorldsBox) {
    const std::string path = fmt::format("{}/examples/scene.vox", VOXC_SOURCE_DIR);
    std::ifstream in(path);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    const std::string small = "size = [96, 64, 96];";
    ASSERT_NE(text.find(small), std::string::npos);
    const std::string large = std::string(text).replace(text.find(small), small.size(), "size = [4096, 64, 4096];");
    EXPECT_TRUE(checkSource(SourceFile(path, large)).hasErrors()); // the whole world is too large to run
    CheckOptions options;
    options.region = std::pair(glm::ivec3(30, 0, 41), glm::ivec3(67, 64, 60));
    CheckResult checked = checkSource(SourceFile(path, large), options);
    ASSERT_FALSE(checked.hasErrors()) << checked.rendered();
    const stages::GridBox region{glm::ivec3(30, 0, 41), glm::ivec3(67, 64, 60)};
    const Program smallWorld = loadExample("scene");
    const glm::ivec3 halo = stages::pipelineHalo(smallWorld).radius;
    ASSERT_TRUE(glm::all(glm::lessThanEqual(region.max + glm::ivec3(halo.x, 0, halo.z), smallWorld.world.size)));
    EXPECT_EQ(test::countVoxelDifferences(stages::cropGrid(interpret(smallWorld), region),
                                          interpretRegion(*checked.program, region)),
              0u);
}

INSTANTIATE_TEST_SUITE_P(examples, RegionOfExample,
                         ::testing::Values("overhang", "cave_grammar", "terrain", "fields", "arch", "cave", "cliff",
                                           "scene", "curves_cliff", "lsystem_cave", "speleothems", "caves", "valley"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

} // namespace
} // namespace voxc
