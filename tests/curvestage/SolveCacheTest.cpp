// Solves kept between runs (voxc/stages/SolveCache.h; docs/curves.md, "Solves kept between runs"):
// with a cache directory, a second run of an unchanged file solves nothing and gets the same bits,
// a region reads the whole block's entry, a changed constraint point or terrain spline solves
// again, and a corrupt entry is ignored, solved again and rewritten whole.
#include "CheckedProgram.h"
#include "Programs.h"

#include "voxc/codegen/CompileCache.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Region.h"
#include "voxc/stages/Solve.h"
#include "voxc/stages/SolveCache.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace voxc {
namespace {

namespace fs = std::filesystem;

const std::string kTerrain = R"(
world { size = [32, 16, 32]; }
material rock { id = 1; }
terrain land {
  max_height = 16;
  levels = [2, 5];
  material = rock;
  preset = mountain_river;
  steps_scale = 0.05;
  spline top { points = [[0, 9, 16], [10, 9, 16], [22, 9, 16], [32, 9, 16]]; radius = 4; left = [8, -4]; right = [8, -4]; hardness = 0.3; }
}
field ground = wy < land(wx, wz) ? 1.0 : 0.0;
pipeline { start; set land; union ground; }
)";

// A cache directory of its own, set for the test and removed after it.
class SolveCache : public testing::Test {
protected:
    void SetUp() override {
        directory_ = fs::temp_directory_path() / ("voxc-solve-cache-" + std::to_string(getpid()));
        fs::remove_all(directory_);
        codegen::setCompileCacheDirectory(directory_);
    }
    void TearDown() override {
        codegen::setCompileCacheDirectory(std::nullopt);
        fs::remove_all(directory_);
    }

    // Solves a fresh check of `text`; returns how many blocks were solved and read.
    stages::SolveCacheCounts run(const std::string& text, Program& program) {
        program = test::checkedProgram("cache.vox", text, test::Allowed::None);
        const stages::SolveCacheCounts before = stages::solveCacheCounts();
        stages::solveBlocks(program);
        const stages::SolveCacheCounts after = stages::solveCacheCounts();
        return {after.solved - before.solved, after.hits - before.hits, after.corrupted - before.corrupted};
    }

    std::vector<fs::path> entries() const {
        std::vector<fs::path> out;
        for (const fs::directory_entry& entry : fs::directory_iterator(directory_ / "solves")) out.push_back(entry.path());
        return out;
    }

    fs::path directory_;
};

void expectSameTable(const SolveTable& a, const SolveTable& b) {
    EXPECT_EQ(a.min, b.min);
    EXPECT_EQ(a.size, b.size);
    ASSERT_EQ(a.density.size(), b.density.size());
    EXPECT_EQ(0, std::memcmp(a.density.data(), b.density.data(), a.density.size() * sizeof(float)));
    EXPECT_EQ(a.material, b.material);
    EXPECT_EQ(a.notes, b.notes);
    ASSERT_EQ(a.solves.size(), b.solves.size());
    for (size_t i = 0; i < a.solves.size(); ++i) EXPECT_EQ(a.solves[i].residuals, b.solves[i].residuals);
}

TEST_F(SolveCache, TheSecondRunSolvesNothingAndAChangedPointSolvesAgain) {
    const std::string text = test::ridgeProgram("union", "");
    Program first, second, changed;
    EXPECT_EQ(run(text, first).solved, 1u);
    const stages::SolveCacheCounts again = run(text, second);
    EXPECT_EQ(again.solved, 0u);
    EXPECT_EQ(again.hits, 1u);
    expectSameTable(first.curves.at(0).solved(), second.curves.at(0).solved());
    const DenseGrid a = interpret(first), b = interpret(second);
    EXPECT_EQ(0, std::memcmp(a.data().data(), b.data().data(), a.data().size() * sizeof(float)));

    // One constraint point moved: that block solves again, to a different table.
    std::string moved = text;
    moved.replace(moved.find("[14, 14, 10]"), 12, "[14, 15, 10]");
    const stages::SolveCacheCounts third = run(moved, changed);
    EXPECT_EQ(third.solved, 1u);
    EXPECT_EQ(third.hits, 0u);
    EXPECT_NE(changed.curves.at(0).solved().density, first.curves.at(0).solved().density);
    EXPECT_EQ(entries().size(), 2u);
}

TEST_F(SolveCache, ARegionReadsTheWholeBlocksEntry) {
    const std::string text = test::ridgeProgram("union", "");
    Program whole;
    run(text, whole);
    const Program unsolved = test::checkedProgram("cache.vox", text, test::Allowed::None);
    const stages::GridBox box{{5, 3, 9}, {30, 21, 20}};
    Program region = stages::regionProgram(unsolved, box);
    const stages::SolveCacheCounts before = stages::solveCacheCounts();
    stages::solveBlocks(region);
    EXPECT_EQ(stages::solveCacheCounts().solved, before.solved);
    EXPECT_EQ(stages::solveCacheCounts().hits, before.hits + 1);
    expectSameTable(region.curves.at(0).solved(), stages::regionProgram(whole, box).curves.at(0).solved());
}

TEST_F(SolveCache, TerrainMapsAreKeptAndFieldsSampleThem) {
    Program first, second, changed;
    EXPECT_EQ(run(kTerrain, first).solved, 1u);
    EXPECT_EQ(run(kTerrain, second).hits, 1u);
    const SolveTable &a = first.curves.at(0).solved(), &b = second.curves.at(0).solved();
    expectSameTable(a, b);
    EXPECT_EQ(a.terrainMaps->height, b.terrainMaps->height);
    EXPECT_EQ(a.terrainMaps->water, b.terrainMaps->water);
    const DenseGrid x = interpret(first), y = interpret(second); // the field samples the kept map
    EXPECT_EQ(0, std::memcmp(x.data().data(), y.data().data(), x.data().size() * sizeof(float)));
    std::string moved = kTerrain;
    moved.replace(moved.find("[10, 9, 16]"), 11, "[10, 11, 16]");
    EXPECT_EQ(run(moved, changed).solved, 1u);
    EXPECT_NE(changed.curves.at(0).solved().terrainMaps->height, a.terrainMaps->height);
}

TEST_F(SolveCache, ACorruptEntryIsIgnoredAndRewritten) {
    const std::string text = test::ridgeProgram("union", "");
    Program first, second, third;
    run(text, first);
    ASSERT_EQ(entries().size(), 1u);
    const fs::path entry = entries().front();
    const uintmax_t size = fs::file_size(entry);
    { // flip a byte in the middle of the densities
        std::fstream file(entry, std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(std::streamoff(size / 2));
        file.put('\x5a');
    }
    const stages::SolveCacheCounts corrupt = run(text, second);
    EXPECT_EQ(corrupt.solved, 1u);
    EXPECT_EQ(corrupt.corrupted, 1u);
    expectSameTable(first.curves.at(0).solved(), second.curves.at(0).solved());
    EXPECT_EQ(fs::file_size(entry), size); // rewritten whole
    fs::resize_file(entry, size / 3);      // truncated
    EXPECT_EQ(run(text, third).corrupted, 1u);
    EXPECT_EQ(run(text, third).hits, 1u);   // and rewritten again
    for (const fs::path& path : entries()) EXPECT_EQ(path.extension(), ".table") << path; // no temp files left
}

TEST_F(SolveCache, ChannelsAreNeverKept) {
    const std::string text = test::ridgeProgram("union", "");
    Program program = test::checkedProgram("cache.vox", text, test::Allowed::None);
    stages::solveBlocks(program, {.keepChannels = true});
    EXPECT_FALSE(fs::exists(directory_ / "solves"));
    EXPECT_FALSE(program.curves.at(0).solved().channels.empty());
}

} // namespace
} // namespace voxc
