// voxc world's tiles (voxc/world/Tiles.h): written, read back from their OpenVDB files and put
// together, they equal the whole world's run; a run stopped after some tiles resumes, keeping
// exactly the tiles whose files still hash as listed, and ends with the same voxels.
#include "GridCompare.h"
#include "voxc/check/Check.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Region.h"
#include "voxc/world/Tiles.h"
#include "voxc/world/VdbTile.h"

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <glm/common.hpp>
#include <gtest/gtest.h>

namespace voxc {
namespace {

namespace fs = std::filesystem;

struct Stop {};

class WorldTiles : public ::testing::Test {
protected:
    void SetUp() override {
        CheckResult checked = checkFile(fmt::format("{}/examples/scene.vox", VOXC_SOURCE_DIR));
        ASSERT_FALSE(checked.hasErrors());
        program = std::move(*checked.program);
        program.world.origin += glm::ivec3(-40, -3, 17);
        directory = fs::temp_directory_path() / fmt::format("voxc_world_tiles_{}", ::getpid());
        fs::remove_all(directory);
    }
    void TearDown() override { fs::remove_all(directory); }

    world::WorldOptions options(int* computed) const {
        world::WorldOptions o;
        o.directory = directory.string();
        o.tile = 40;
        o.sourceText = "scene";
        o.run = [computed](const Program& region) {
            ++*computed;
            return interpret(region);
        };
        return o;
    }

    // Every tile read back and put in place.
    DenseGrid readBack() const {
        const glm::ivec3 size = program.world.size;
        DenseGrid all(size);
        const glm::ivec3 tiles = (size + 39) / 40;
        for (int k = 0; k < tiles.z; ++k)
            for (int j = 0; j < tiles.y; ++j)
                for (int i = 0; i < tiles.x; ++i) {
                    const glm::ivec3 min = glm::ivec3(i, j, k) * 40, max = glm::min(min + 40, size);
                    const DenseGrid tile = world::readTileVdb((directory / world::tileFileName({i, j, k})).string(),
                                                              program.world.origin + min, max - min);
                    for (int z = min.z; z < max.z; ++z)
                        for (int y = min.y; y < max.y; ++y)
                            for (int x = min.x; x < max.x; ++x) {
                                all.at({x, y, z}) = tile.at(glm::ivec3(x, y, z) - min);
                                all.materialAt({x, y, z}) = tile.materialAt(glm::ivec3(x, y, z) - min);
                            }
                }
        return all;
    }

    Program program;
    fs::path directory;
};

TEST_F(WorldTiles, ReadBackEqualTheWholeWorld) {
    int computed = 0;
    const world::WorldSummary summary = world::writeWorld(program, options(&computed));
    EXPECT_EQ(summary.tiles, 3 * 2 * 3);
    EXPECT_EQ(computed, 18);
    EXPECT_EQ(test::countVoxelDifferences(interpret(program), readBack()), 0u);
}

TEST_F(WorldTiles, AStoppedRunResumes) {
    int computed = 0;
    world::WorldOptions first = options(&computed);
    first.progress = [](const world::TileProgress& progress) {
        if (progress.done == 7) throw Stop{};
    };
    EXPECT_THROW(world::writeWorld(program, first), Stop);
    EXPECT_EQ(computed, 7);
    // A tile whose file changed since it was listed is computed again.
    {
        std::fstream file(directory / world::tileFileName({1, 0, 0}), std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(40);
        file.put('\x5a');
    }
    computed = 0;
    const world::WorldSummary summary = world::writeWorld(program, options(&computed));
    EXPECT_EQ(summary.kept, 6);
    EXPECT_EQ(computed, 18 - 6);
    EXPECT_EQ(test::countVoxelDifferences(interpret(program), readBack()), 0u);
    computed = 0;
    EXPECT_EQ(world::writeWorld(program, options(&computed)).kept, 18); // all up to date
    EXPECT_EQ(computed, 0);
}

TEST_F(WorldTiles, AnotherWorldsDirectoryIsRefused) {
    int computed = 0;
    world::WorldOptions o = options(&computed);
    o.progress = [](const world::TileProgress&) { throw Stop{}; };
    EXPECT_THROW(world::writeWorld(program, o), Stop);
    o.progress = {};
    o.tile = 32;
    EXPECT_THROW(world::writeWorld(program, o), UserError);
}

} // namespace
} // namespace voxc
