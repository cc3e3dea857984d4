// Equal-sized tiles of a world compile to the same kernels: a tile's place reaches the kernels as
// run-time input (its grid origin in the push constants), never as GLSL text, so a world's
// tiles share one set of pipelines (ContextOptions::shareKernelPipelines; docs/scale.md).
#include "GridCompare.h"
#include "voxc/check/Check.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Region.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"
#include "voxc/world/Tiles.h"
#include "voxc/world/VdbTile.h"

#include <filesystem>
#include <fmt/format.h>
#include <glm/common.hpp>
#include <gtest/gtest.h>
#include <set>
#include <sstream>
#include <unistd.h>

namespace voxc {
namespace {

namespace fs = std::filesystem;

// The first lines where two kernels' sources differ, for the failure message.
std::string firstDifferences(const std::string& a, const std::string& b) {
    std::istringstream ia(a), ib(b);
    std::string la, lb, out;
    for (int line = 1, shown = 0; shown < 4; ++line) {
        const bool moreA = bool(std::getline(ia, la)), moreB = bool(std::getline(ib, lb));
        if (!moreA && !moreB) break;
        if (!moreA) la.clear();
        if (!moreB) lb.clear();
        if (la == lb) continue;
        out += fmt::format("line {}:\n  - {}\n  + {}\n", line, la, lb);
        ++shown;
    }
    return out;
}

Program example(const std::string& name) {
    CheckResult checked = checkFile(fmt::format("{}/examples/{}.vox", VOXC_SOURCE_DIR, name));
    EXPECT_FALSE(checked.hasErrors()) << checked.rendered();
    Program program = std::move(*checked.program);
    program.world.origin += glm::ivec3(-37, 5, -21);
    return program;
}

class TileKernels : public ::testing::TestWithParam<std::string> {};

// Two boxes of one size, moved apart by an amount no chunk size or grammar stride divides, in
// every axis: the same kernels, SPIR-V word for word. Not yet for grammars with stamps
// (mesa_burrows, sea_caves): their sweep and stamp kernels are written for the box's own anchor
// lattice (StampKernel.cpp), so tiles where it starts elsewhere compile their own.
TEST_P(TileKernels, EqualBoxesCompileToTheSameKernels) {
    const Program program = example(GetParam());
    const glm::ivec3 size = program.world.size / 3;
    const glm::ivec3 shift = glm::min(glm::ivec3(13, 7, 11), program.world.size - 2 * size);
    const stages::GridBox first{glm::ivec3(2, 1, 3), glm::ivec3(2, 1, 3) + size};
    const stages::GridBox second{first.min + shift, first.max + shift};
    const KernelPackage a = compileProgram(stages::regionProgram(program, first));
    const KernelPackage b = compileProgram(stages::regionProgram(program, second));
    ASSERT_EQ(a.kernels.size(), b.kernels.size());
    for (size_t k = 0; k < a.kernels.size(); ++k)
        EXPECT_TRUE(a.kernels[k].spirv == b.kernels[k].spirv)
            << a.kernels[k].name << "\n" << firstDifferences(a.kernels[k].glsl, b.kernels[k].glsl);
}

INSTANTIATE_TEST_SUITE_P(examples, TileKernels,
                         ::testing::Values("scene", "overhang", "cave", "curves_cliff", "speleothems", "mountains",
                                           "fields", "lsystem_branches", "lsystem_cave", "terrain", "canyon", "valley", "caves"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// `voxc world` on a context that shares kernel pipelines: the driver compiles each distinct
// kernel once however many tiles use it, the validation layer accepts a pipeline bound with
// another executor's (identically defined) layout, and the tiles still equal the interpreter's
// whole world.
TEST(TileKernelsOnLavapipe, AWorldCreatesEachDistinctPipelineOnce) {
    const Program program = example("scene");
    const fs::path directory = fs::temp_directory_path() / fmt::format("voxc_tile_kernels_{}", ::getpid());
    fs::remove_all(directory);
    VulkanContext context(ContextOptions{.device = "lavapipe", .validation = true, .shareKernelPipelines = true});
    world::WorldOptions options;
    options.directory = directory.string();
    options.tile = 32;
    options.sourceText = "scene";
    options.meshFormat = "";
    std::set<std::vector<uint32_t>> distinct;
    uint64_t kernels = 0;
    options.run = [&](const Program& region) {
        const KernelPackage package = compileProgram(region);
        for (const Kernel& kernel : package.kernels) distinct.insert(kernel.spirv);
        kernels += package.kernels.size();
        VulkanExecutor executor(context, package);
        return executor.run().grid.toDense();
    };
    const world::WorldSummary summary = world::writeWorld(program, options);
    EXPECT_EQ(summary.tiles, 18); // 96 x 64 x 96 in tiles of 32

    const KernelPipelineCounts counts = context.kernelPipelineCounts();
    EXPECT_EQ(counts.created, distinct.size());
    EXPECT_EQ(counts.created + counts.shared, kernels);
    EXPECT_LE(counts.created * 4, kernels) << "18 tiles of two sizes should share most kernels";
    for (const ValidationMessage& message : context.validationMessages()) ADD_FAILURE() << message.text;

    const DenseGrid whole = interpret(program);
    for (int32_t z = 0; z < 3; ++z)
        for (int32_t y = 0; y < 2; ++y)
            for (int32_t x = 0; x < 3; ++x) {
                const glm::ivec3 tile(x, y, z);
                const DenseGrid read = world::readTileVdb((directory / world::tileFileName(tile)).string(),
                                                          program.world.origin + tile * 32, glm::ivec3(32));
                EXPECT_EQ(test::countVoxelDifferences(stages::cropGrid(whole, {tile * 32, tile * 32 + 32}), read), 0u)
                    << "tile " << x << "," << y << "," << z;
            }
    fs::remove_all(directory);
}

} // namespace
} // namespace voxc
