// Constant overrides re-check the program; explore() runs the sweep and summarises it.
#include "voxc/check/Check.h"
#include "voxc/core/Errors.h"
#include "voxc/explore/Explore.h"
#include "voxc/explore/Report.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/stages/Pipeline.h"

#include <algorithm>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using namespace voxc;
using namespace voxc::explore;

namespace {

// Every voxel starts at 0.4; the rule raises it to 1 where it is at least T. Shape keys and
// the world seed use constants too.
const char* kThreshold = R"(
const T = 0.5;
const R = 2;
const S = 7;
world { size = [8, 8, 8]; seed = S * 2; }
start { fill { value = 0.4; } sphere { center = [4, 4, 4]; radius = R; value = 0; } }
grammar raise {
  rule up { size = [1, 1, 1]; symbol { [GEQ T] } transform { [SET 1] } }
}
)";

SourceFile erodeSource() {
    const std::string path = std::string(VOXC_EXPLORE_TEST_DIR) + "/erode.vox";
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return SourceFile(path, text.str());
}

ExploreSettings erodeSettings() {
    ExploreSettings settings;
    settings.parameter = "P";
    settings.values = {0.0, 0.5, 1.0};
    settings.runs = 3;
    return settings;
}

} // namespace

TEST(ExploreOverride, EveryUseOfTheConstantSeesTheNewValue) {
    const SourceFile source("t.vox", kThreshold);
    const Program low = checkWithParameter(source, "T", 0.3);
    const Program high = checkWithParameter(source, "T", 0.5);
    EXPECT_FLOAT_EQ(low.grammars[0].rules[0].symbol[0].predicates[0].value, 0.3f);
    // 0.4 passes GEQ 0.3, so everything outside the sphere becomes rock; with GEQ 0.5 nothing does.
    const double lowFraction = describeVolume(interpret(low), 0.5f).solidFraction;
    EXPECT_GT(lowFraction, 0.9);
    EXPECT_LT(lowFraction, 1.0);
    EXPECT_DOUBLE_EQ(describeVolume(interpret(high), 0.5f).solidFraction, 0.0);

    EXPECT_EQ(checkWithParameter(source, "S", 100).world.seed, 200u);
    EXPECT_FLOAT_EQ(checkWithParameter(source, "R", 3).start[1].radius, 3.0f);
}

TEST(ExploreOverride, ConstantsFoldedFromTheOverriddenOneFollowIt) {
    const SourceFile source("t.vox", "const A = 1;\nconst B = A * 4;\nworld { size = [B, 2, 2]; }\n");
    EXPECT_EQ(checkWithParameter(source, "A", 2).world.size.x, 8);
}

TEST(ExploreOverride, UnknownConstantIsE0002) {
    CheckOptions options;
    options.constOverrides["ROK"] = 0.5;
    const CheckResult result = checkSource(SourceFile("t.vox", "const ROCK = 1;\nworld { size = [2, 2, 2]; }\n"), options);
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].code, "E0002");
    EXPECT_NE(result.diagnostics[0].message.find("did you mean 'ROCK'"), std::string::npos);
    EXPECT_THROW(checkWithParameter(SourceFile("t.vox", kThreshold), "NOPE", 1), UserError);
}

TEST(ExploreOverride, AnInvalidValueIsALocatedError) {
    try {
        checkWithParameter(erodeSource(), "P", 1.5);
        FAIL() << "expected a UserError";
    } catch (const UserError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("with P = 1.5"), std::string::npos) << message;
        EXPECT_NE(message.find("erode.vox:18:19: error E0007"), std::string::npos) << message;
    }
}

TEST(Explore, SeedsAndParameterChangeTheDescriptors) {
    const ExploreResult result = runExploration(erodeSource(), erodeSettings());
    ASSERT_EQ(result.values.size(), 3u);
    const ValueSummary& none = result.values[0];
    const ValueSummary& half = result.values[1];
    const ValueSummary& all = result.values[2];
    ASSERT_EQ(none.runs.size(), 3u);
    EXPECT_EQ(none.runs[0].seed, 5u);
    EXPECT_EQ(none.runs[2].seed, 7u);
    // P = 0: nothing is removed, whatever the seed.
    EXPECT_GT(none.solidFraction.mean, 0.2);
    EXPECT_DOUBLE_EQ(none.solidFraction.stddev, 0.0);
    EXPECT_DOUBLE_EQ(none.iou->mean, 1.0);
    // P = 0.5: about half is removed, differently for each seed.
    EXPECT_NEAR(half.solidFraction.mean, none.solidFraction.mean / 2, none.solidFraction.mean * 0.1);
    EXPECT_GT(half.solidFraction.stddev, 0.0);
    EXPECT_LT(half.iou->mean, 0.5);
    EXPECT_GT(half.surfaceArea.mean, none.surfaceArea.mean);
    // P = 1: everything is removed; two empty sets are identical.
    EXPECT_DOUBLE_EQ(all.solidFraction.mean, 0.0);
    EXPECT_DOUBLE_EQ(all.surfaceArea.mean, 0.0);
    EXPECT_DOUBLE_EQ(all.iou->mean, 1.0);
}

TEST(Explore, SeedBaseSizeOverrideAndDeterminism) {
    ExploreSettings settings = erodeSettings();
    settings.seedBase = 100;
    settings.size = glm::ivec3{10, 12, 14};
    const ExploreResult first = runExploration(erodeSource(), settings);
    EXPECT_EQ(first.size, glm::ivec3(10, 12, 14));
    EXPECT_EQ(first.values[1].runs[1].seed, 101u);
    EXPECT_EQ(formatRunsCsv(first), formatRunsCsv(runExploration(erodeSource(), settings)));
}

TEST(Explore, ResizeClipsGrammarBounds) {
    Program program = checkWithParameter(erodeSource(), "P", 0.5);
    resizeWorld(program, {6, 30, 6});
    EXPECT_EQ(program.grammars[0].boundsMin, glm::ivec3(0, 0, 0));
    EXPECT_EQ(program.grammars[0].boundsMax, glm::ivec3(6, 20, 6));
}

TEST(Explore, ValidatesSettings) {
    ExploreSettings settings = erodeSettings();
    settings.runs = 0;
    EXPECT_THROW(runExploration(erodeSource(), settings), UserError);
    settings.runs = kMaxRuns + 1;
    EXPECT_THROW(runExploration(erodeSource(), settings), UserError);
    settings = erodeSettings();
    settings.size = glm::ivec3{0, 4, 4};
    EXPECT_THROW(runExploration(erodeSource(), settings), UserError);
}

TEST(ExploreReport, CsvRowsAndSummary) {
    ExploreSettings settings = erodeSettings();
    settings.values = {0.0, 0.25};
    settings.runs = 2;
    const ExploreResult result = runExploration(erodeSource(), settings);
    const std::string runs = formatRunsCsv(result);
    const VolumeDescriptors& d = result.values[0].runs[1].descriptors;
    EXPECT_EQ(runs.substr(0, runs.find('\n')), "parameter,value,run,seed,solid_fraction,surface_area");
    EXPECT_NE(runs.find(fmt::format("\nP,0,1,6,{},{}\n", d.solidFraction, d.surfaceArea)), std::string::npos) << runs;
    EXPECT_EQ(std::count(runs.begin(), runs.end(), '\n'), 5);
    EXPECT_NE(runs.find("\nP,0.25,1,6,"), std::string::npos);

    const std::string summary = formatSummaryCsv(result);
    EXPECT_EQ(summary.substr(0, summary.find('\n')),
              "parameter,value,runs,solid_fraction_mean,solid_fraction_stddev,surface_area_mean,"
              "surface_area_stddev,iou_mean,iou_stddev");
    EXPECT_NE(summary.find(fmt::format("\nP,0,2,{},0,{},0,1,0\n", d.solidFraction, d.surfaceArea)), std::string::npos)
        << summary;

    settings.runs = 1; // no pairs: the IoU columns are empty
    const std::string single = formatSummaryCsv(runExploration(erodeSource(), settings));
    EXPECT_NE(single.find(",0,,\n"), std::string::npos) << single;
}
