// The pipeline's work estimate against Limits::maxWork (what `--max-work` sets), and the bound
// on rules x window cells of one sweep.
#include "CheckTestUtil.h"

#include <gtest/gtest.h>

namespace voxc {
namespace work_estimate_test {

using test::codes;
using Codes = std::vector<std::string>;

// A 16^3 world and a 100000-iteration grammar with one 3x3x1 rule, run `runs` times, one
// pipeline entry per line from line 13 on. One run tests 14 * 14 * 16 anchors x 9 cells per
// iteration: 2.8224e9 cells, so the default budget of 1e11 admits 35 runs.
std::string repeatedGrammar(int runs) {
    std::string text = test::oneRule("[3, 3, 1]", "[GEQ 0.5, IGN, IGN] [IGN, IGN, IGN] [IGN, IGN, IGN]",
                                     "[NOP, NOP, NOP] [NOP, SET 1, NOP] [NOP, NOP, NOP]", "", "iterations = 100000;");
    text += "pipeline {\n  start;\n";
    for (int i = 0; i < runs; ++i) text += "  g;\n";
    return text + "}\n";
}

TEST(check_Work, RepeatedLongGrammarsPassTheBudgetAtTheStage) {
    CheckResult admitted = test::check(repeatedGrammar(35));
    EXPECT_FALSE(admitted.hasErrors()) << admitted.rendered();
    CheckResult result = test::check(repeatedGrammar(1000));
    ASSERT_EQ(codes(result), Codes{"E0012"}) << result.rendered();
    const Diagnostic& error = result.diagnostics[0];
    EXPECT_EQ(error.loc.line, 13u + 35u); // the 36th run of g
    EXPECT_EQ(error.loc.column, 3u);
    EXPECT_NE(error.message.find("budget of 1e+11"), std::string::npos) << error.message;
    EXPECT_NE(error.message.find("grammar 'g' (100000 iterations x 2.82e+04"), std::string::npos) << error.message;
    EXPECT_NE(error.message.find("--max-work"), std::string::npos);
}

TEST(check_Work, ARaisedBudgetAdmitsTheRun) {
    Limits limits;
    limits.maxWork = int64_t(3) * 1000 * 1000 * 1000 * 1000;
    EXPECT_FALSE(checkSource(SourceFile("t.vox", repeatedGrammar(1000)), limits).hasErrors());
    limits.maxWork = int64_t(2) * 1000 * 1000 * 1000 * 1000;
    EXPECT_EQ(codes(checkSource(SourceFile("t.vox", repeatedGrammar(1000)), limits)), Codes{"E0012"});
}

// Start shapes cost a pass over the grid each; the error points at the shape that passes.
TEST(check_Work, StartShapesCountEachVoxel) {
    Limits limits;
    limits.maxWork = 3 * 16 * 16 * 16;
    const std::string shapes = "world { size = [16, 16, 16]; }\nstart {\n  fill { value = 0; }\n"
                               "  sphere { center = [8, 8, 8]; radius = 4; }\n  box { min = [0, 0, 0]; max = [4, 4, 4]; }\n";
    EXPECT_FALSE(checkSource(SourceFile("t.vox", shapes + "}\n"), limits).hasErrors());
    CheckResult result = checkSource(SourceFile("t.vox", shapes + "  fill { value = 1; }\n}\n"), limits);
    ASSERT_EQ(codes(result), Codes{"E0012"}) << result.rendered();
    EXPECT_EQ(result.diagnostics[0].loc.line, 6u);
    EXPECT_NE(result.diagnostics[0].message.find("the start state (4 shapes x 4.1e+03 voxels)"), std::string::npos)
        << result.diagnostics[0].message;
}

TEST(check_Work, FieldStagesCountVoxelsTimesNodes) {
    Limits limits;
    limits.maxWork = 8 * 8 * 8 * 3; // one stage of `x + 1`: input, constant, add
    const std::string text = "world { size = [8, 8, 8]; }\nfield f = x + 1;\npipeline {\n  start;\n  union f;\n";
    EXPECT_FALSE(checkSource(SourceFile("t.vox", text + "}\n"), limits).hasErrors());
    CheckResult result = checkSource(SourceFile("t.vox", text + "  subtract f;\n}\n"), limits);
    ASSERT_EQ(codes(result), Codes{"E0012"}) << result.rendered();
    EXPECT_EQ(result.diagnostics[0].loc.line, 6u);
    EXPECT_NE(result.diagnostics[0].message.find("field 'f' (512 voxels x 3 nodes)"), std::string::npos);
}

// Rules of one size compile into one kernel that tests all their cells.
TEST(check_Work, RulesTimesCellsPerSweepAreBounded) {
    Limits limits;
    limits.maxSweepRuleCells = 20;
    auto rules = [](int count) {
        std::string text = "world { size = [16, 16, 16]; }\ngrammar g {\n";
        for (int i = 0; i < count; ++i)
            text += "  rule r" + std::to_string(i) +
                    " { size = [3, 3, 1]; symbol { [GEQ 0.5, IGN, IGN] [IGN, IGN, IGN] [IGN, IGN, IGN] } "
                    "transform { [SET 0, NOP, NOP] [NOP, NOP, NOP] [NOP, NOP, NOP] } }\n";
        return text + "}\n";
    };
    EXPECT_FALSE(checkSource(SourceFile("t.vox", rules(2)), limits).hasErrors());
    CheckResult result = checkSource(SourceFile("t.vox", rules(5)), limits);
    ASSERT_EQ(codes(result), Codes{"E0012"}) << result.rendered();
    EXPECT_EQ(result.diagnostics[0].loc.line, 5u); // r2, the third rule of size [3, 3, 1]
    EXPECT_EQ(result.diagnostics[0].loc.column, 8u);
    EXPECT_NE(result.diagnostics[0].message.find("3 x 9 window cells"), std::string::npos);
}

TEST(check_Work, StartShapesAreBounded) {
    Limits limits;
    limits.maxStartShapes = 2;
    const std::string head = "world { size = [8, 8, 8]; }\nstart {\n  fill { value = 0; }\n  fill { value = 1; }\n";
    EXPECT_FALSE(checkSource(SourceFile("t.vox", head + "}\n"), limits).hasErrors());
    CheckResult result = checkSource(SourceFile("t.vox", head + "  fill { value = 0.5; }\n}\n"), limits);
    ASSERT_EQ(codes(result), Codes{"E0012"}) << result.rendered();
    EXPECT_EQ(result.diagnostics[0].loc.line, 5u);
    EXPECT_EQ(result.diagnostics[0].loc.column, 3u);
    EXPECT_NE(result.diagnostics[0].message.find("3 shapes, more than the limit of 2"), std::string::npos);
}

TEST(check_Work, TestsPerCellAreBounded) {
    auto cell = [](int tests) {
        std::string text = "GEQ 0";
        for (int i = 1; i < tests; ++i) text += " & GEQ 0." + std::to_string(i);
        return "[" + text + "]";
    };
    EXPECT_FALSE(test::check(test::oneRule("[1, 1, 1]", cell(32), "[SET 1]")).hasErrors());
    CheckResult result = test::check(test::oneRule("[1, 1, 1]", cell(33), "[SET 1]"));
    ASSERT_EQ(codes(result), Codes{"E0012"}) << result.rendered();
    EXPECT_EQ(result.diagnostics[0].loc.line, 7u);
    EXPECT_EQ(result.diagnostics[0].loc.column, 15u);
    EXPECT_NE(result.diagnostics[0].message.find("joins 33 tests"), std::string::npos);
}

// Each distinct field stage compiles into a kernel; repeating one does not.
TEST(check_Work, DistinctKernelsAreBounded) {
    Limits limits;
    limits.maxKernels = 3;
    const std::string head = "world { size = [8, 8, 8]; }\nfield a = x;\nfield b = y;\npipeline {\n  start;\n"
                             "  union a;\n  union a;\n  subtract a;\n  union b;\n";
    EXPECT_FALSE(checkSource(SourceFile("t.vox", head + "  union b;\n}\n"), limits).hasErrors());
    CheckResult result = checkSource(SourceFile("t.vox", head + "  set b;\n}\n"), limits);
    ASSERT_EQ(codes(result), Codes{"E0012"}) << result.rendered();
    EXPECT_EQ(result.diagnostics[0].loc.line, 10u);
    EXPECT_NE(result.diagnostics[0].message.find("needs 4 kernels"), std::string::npos);
}

} // namespace work_estimate_test
} // namespace voxc
