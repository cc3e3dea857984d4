// The examples this component maintains must check without any diagnostic.
#include "voxc/check/Check.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace voxc {
namespace {

class check_Examples : public testing::TestWithParam<std::string> {};

TEST_P(check_Examples, CheckCleanly) {
    CheckResult result = checkFile(std::string(VOXC_EXAMPLES_DIR) + "/" + GetParam() + ".vox");
    EXPECT_TRUE(result.diagnostics.empty()) << result.rendered();
    ASSERT_TRUE(result.program.has_value());
    EXPECT_FALSE(result.program->grammars.empty());
    for (const Grammar& grammar : result.program->grammars) EXPECT_FALSE(grammar.rules.empty());
}

INSTANTIATE_TEST_SUITE_P(files, check_Examples, testing::Values("overhang", "cave_grammar", "terrain"));

// Every example, grammar or not, checks without a diagnostic: no unused declaration (W0206-W0208),
// and well inside every limit, the work budget included.
TEST(check_Examples, EveryExampleChecksWithoutWarnings) {
    size_t examples = 0;
    for (const auto& entry : std::filesystem::directory_iterator(VOXC_EXAMPLES_DIR)) {
        if (entry.path().extension() != ".vox") continue;
        ++examples;
        Limits limits;
        limits.maxWork /= 100;
        CheckResult result = checkFile(entry.path().string(), limits);
        EXPECT_TRUE(result.diagnostics.empty()) << result.rendered();
    }
    EXPECT_GE(examples, 8u);
}

TEST(check_Examples, OverhangIsDeyTable33) {
    CheckResult result = checkFile(std::string(VOXC_EXAMPLES_DIR) + "/overhang.vox");
    ASSERT_TRUE(result.program) << result.rendered();
    const Grammar& grammar = result.program->grammars.at(0);
    ASSERT_EQ(grammar.rules.size(), 4u);
    // Rule 1: bottom-left transform cell (printed last row, first column) erodes by 0.5.
    const Rule& erode = grammar.rules[0];
    EXPECT_EQ(erode.size, glm::ivec3(3, 3, 1));
    EXPECT_EQ(erode.transform[cellIndex(erode.size, 0, 0, 0)].op, TransformOp::ADD);
    EXPECT_EQ(erode.transform[cellIndex(erode.size, 0, 0, 0)].value, -0.5f);
    // Rule 3: the top row is all GEQ 0.5.
    const Rule& ledge = grammar.rules[2];
    for (int x = 0; x < 3; ++x) EXPECT_EQ(ledge.symbol[cellIndex(ledge.size, x, 2, 0)].predicates.at(0).op, SymbolOp::GEQ);
}

} // namespace
} // namespace voxc
