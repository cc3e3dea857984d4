// Non-finite values (docs/language.md, "Non-finite values") on both backends: cases/nonfinite.vox
// makes NaN and infinities inside field expressions, field values that are not finite and a
// grammar ADD past the float range. The grids are compared bit for bit by InterpVsVulkanTest;
// here every density must be finite and both backends must count the same replacements per
// stage, through the staging path and without tile skipping too.
#include "Lavapipe.h"
#include "GridCompare.h"
#include "NonFiniteReport.h"
#include "voxc/check/Check.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace voxc {
namespace non_finite_test {

using test::lavapipe;

Program nonFiniteCase() {
    CheckResult result = checkFile(fmt::format("{}/tests/e2e/cases/nonfinite.vox", VOXC_SOURCE_DIR));
    EXPECT_FALSE(result.hasErrors());
    return std::move(*result.program);
}

size_t countNonFinite(const DenseGrid& grid) {
    size_t n = 0;
    for (float d : grid.data()) n += !std::isfinite(d);
    return n;
}

// The pipeline index of the stage written at `loc`.
size_t pipelineIndex(const Program& program, SourceLoc loc) {
    for (size_t i = 0; i < program.pipeline.size(); ++i)
        if (program.pipeline[i].loc.line == loc.line && program.pipeline[i].loc.column == loc.column) return i;
    ADD_FAILURE() << "no pipeline stage at " << loc.line << ":" << loc.column;
    return 0;
}

// The pipeline index of the field stage of field `name`.
size_t fieldStage(const Program& program, const std::string& name) {
    for (size_t i = 0; i < program.pipeline.size(); ++i) {
        const Stage& stage = program.pipeline[i];
        if (stage.kind == Stage::Kind::Field && program.fields[stage.index].name == name) return i;
    }
    ADD_FAILURE() << "no field stage of " << name;
    return 0;
}

TEST(NonFinite, InterpreterReplacesAndCountsPerStage) {
    const Program program = nonFiniteCase();
    std::vector<NonFiniteCount> counts;
    const DenseGrid grid = interpret(program, InterpOptions{.nonFinite = &counts});
    EXPECT_EQ(countNonFinite(grid), 0u);
    ASSERT_EQ(counts.size(), program.pipeline.size());
    const glm::ivec3 size = program.world.size;
    const uint64_t voxels = uint64_t(size.x) * size.y * size.z;
    // 1 / (x - x), inf - inf and 1e10^(10 + y) are not finite anywhere.
    for (const char* field : {"pole", "gap", "huge"}) {
        SCOPED_TRACE(field);
        EXPECT_EQ(counts[fieldStage(program, field)].count, voxels);
        EXPECT_EQ(counts[fieldStage(program, field)].firstIndex, 0u);
    }
    // clamp and min / max ignore a NaN operand; a comparison with NaN is false: all finite.
    for (const char* field : {"slope", "ignored", "compared"})
        EXPECT_EQ(counts[fieldStage(program, field)].count, 0u) << field;
    // The grammar adds 3e38 to every voxel of `slab` (y < 4), overflowing each once.
    size_t grammarStage = 0;
    while (program.pipeline[grammarStage].kind != Stage::Kind::Grammar) ++grammarStage;
    EXPECT_EQ(counts[grammarStage].count, uint64_t(size.x) * 4 * size.z);
}

TEST(NonFinite, VulkanCountsWhatTheInterpreterCounts) {
    const Program program = nonFiniteCase();
    std::vector<NonFiniteCount> expected;
    const DenseGrid interpreted = interpret(program, InterpOptions{.nonFinite = &expected});
    const KernelPackage package = compileProgram(program, {});
    for (const ExecutorOptions& options : {ExecutorOptions{}, ExecutorOptions{.alwaysStage = true},
                                           ExecutorOptions{.skipInactiveTiles = false}}) {
        SCOPED_TRACE(fmt::format("staged {}, skipping tiles {}", options.alwaysStage, options.skipInactiveTiles));
        VulkanExecutor executor(lavapipe(), package, options);
        const RunResult result = executor.run();
        const DenseGrid actual = result.grid.toDense();
        EXPECT_EQ(test::countBitDifferences(interpreted, actual), 0u);
        EXPECT_EQ(countNonFinite(actual), 0u);
        ASSERT_EQ(result.nonFinite.size(), package.stages.size());
        // Every stage of this pipeline runs (none is dead), each counted as the interpreter does.
        ASSERT_EQ(package.stages.size(), program.pipeline.size());
        for (size_t s = 0; s < package.stages.size(); ++s) {
            const NonFiniteCount& cpu = expected[pipelineIndex(program, package.stages[s].loc)];
            SCOPED_TRACE(fmt::format("stage {}", s));
            EXPECT_EQ(result.nonFinite[s].count, cpu.count);
            if (cpu.count) { EXPECT_EQ(result.nonFinite[s].firstIndex, cpu.firstIndex); }
        }
    }
}

// `voxc interp` and `voxc run` print the same warning lines: one per stage with replacements,
// located at the stage and naming it, with the count.
TEST(NonFinite, InterpAndRunReportTheSameWarnings) {
    const Program program = nonFiniteCase();
    std::vector<NonFiniteCount> counts;
    interpret(program, InterpOptions{.nonFinite = &counts});
    std::vector<SourceLoc> pipelineLocs;
    for (const Stage& stage : program.pipeline) pipelineLocs.push_back(stage.loc);
    const std::string interpLines = driver::formatNonFiniteWarnings(program, "nonfinite.vox", pipelineLocs, counts);

    const KernelPackage package = compileProgram(program, {});
    VulkanExecutor executor(lavapipe(), package);
    const RunResult result = executor.run();
    std::vector<SourceLoc> packageLocs;
    for (const StagePlan& stage : package.stages) packageLocs.push_back(stage.loc);
    EXPECT_EQ(driver::formatNonFiniteWarnings(program, "nonfinite.vox", packageLocs, result.nonFinite), interpLines);

    const Stage& pole = program.pipeline[fieldStage(program, "pole")];
    const glm::ivec3 size = program.world.size;
    EXPECT_NE(interpLines.find(fmt::format("nonfinite.vox:{}:{}: warning: stage `union pole`: {} non-finite densities",
                                           pole.loc.line, pole.loc.column, uint64_t(size.x) * size.y * size.z)),
              std::string::npos)
        << interpLines;
    size_t lines = 0;
    for (const NonFiniteCount& count : counts) lines += count.count > 0;
    EXPECT_EQ(size_t(std::count(interpLines.begin(), interpLines.end(), '\n')), lines);
    EXPECT_EQ(interpLines.find("slope"), std::string::npos); // no replacement, no line
}

// The counters restart with every run of an executor.
TEST(NonFinite, CountsDoNotAccumulateOverRuns) {
    const Program program = nonFiniteCase();
    VulkanExecutor executor(lavapipe(), compileProgram(program, {}));
    const std::vector<NonFiniteCount> first = executor.run().nonFinite;
    const std::vector<NonFiniteCount> second = executor.run().nonFinite;
    ASSERT_EQ(first.size(), second.size());
    for (size_t s = 0; s < first.size(); ++s) EXPECT_EQ(first[s].count, second[s].count) << "stage " << s;
}

} // namespace non_finite_test
} // namespace voxc
