// `where` blocks: what the checker makes of each key, the boxes, and its errors.
#include "CheckTestUtil.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <gtest/gtest.h>

namespace voxc {
namespace aggregates_check_test {

using test::check;
using test::codes;
using Codes = std::vector<std::string>;

// One [3, 5, 1] rule (15 cells) with the given `where` blocks.
std::string ruleWhere(const std::string& where, const std::string& extra = "") {
    return "world { size = [16, 16, 16]; }\nmaterial rock { id = 3; color = [1, 1, 1]; }\ngrammar g {\n"
           "  rule r {\n    size = [3, 5, 1];\n" + extra +
           "    symbol { [IGN, IGN, IGN] [IGN, IGN, IGN] [IGN, IGN, IGN] [IGN, IGN, IGN] [IGN, IGN, IGN] }\n"
           "    transform { [NOP, NOP, NOP] [NOP, NOP, NOP] [NOP, NOP, NOP] [NOP, NOP, NOP] [SET 1, NOP, NOP] }\n" +
           where + "\n  }\n}\n";
}

std::vector<AggregateTest> testsOf(const CheckResult& result, size_t rule = 0) {
    EXPECT_TRUE(result.program.has_value()) << result.rendered();
    if (!result.program) return {};
    return result.program->grammars.at(0).rules.at(rule).aggregates;
}

TEST(check_Aggregates, FractionsBecomeCellCounts) {
    const CheckResult result = check(ruleWhere("where { solid_fraction = [0.4, 0.8]; }"));
    const auto tests = testsOf(result);
    ASSERT_EQ(tests.size(), 1u);
    EXPECT_EQ(tests[0].kind, AggregateKind::SolidFraction);
    EXPECT_EQ(tests[0].minCount, 6u); // 0.4 * 15 = 6 exactly, not 6.000000000000001
    EXPECT_EQ(tests[0].maxCount, 12u);
    EXPECT_EQ(tests[0].boxMin, glm::ivec3(0, 0, 0));
    EXPECT_EQ(tests[0].boxMax, glm::ivec3(3, 5, 1));
}

TEST(check_Aggregates, EveryKindInKeyOrderOverItsBox) {
    const CheckResult result = check(ruleWhere(
        "where low { box = [[0, 0, 0], [2, 2, 1]]; material_fraction = [rock, 0.5, 1]; max = [0, 1]; "
        "mean = [0.25, 0.5]; min = [0.5, 2]; }"));
    const auto tests = testsOf(result);
    ASSERT_EQ(tests.size(), 4u);
    EXPECT_EQ(tests[0].kind, AggregateKind::Mean);
    EXPECT_EQ(tests[0].low, 1.0f); // the mean's bounds bound the sum of the box's 4 cells
    EXPECT_EQ(tests[0].high, 2.0f);
    EXPECT_EQ(tests[1].kind, AggregateKind::Min);
    EXPECT_EQ(tests[2].kind, AggregateKind::Max);
    EXPECT_EQ(tests[3].kind, AggregateKind::MaterialFraction);
    EXPECT_EQ(tests[3].material, 3u);
    EXPECT_EQ(tests[3].minCount, 2u);
    EXPECT_EQ(tests[3].maxCount, 4u);
    for (const AggregateTest& t : tests) EXPECT_EQ(t.boxMax, glm::ivec3(2, 2, 1));
}

TEST(check_Aggregates, SymmetryTurnsTheBox) {
    const CheckResult result =
        check(ruleWhere("where { box = [[0, 0, 0], [1, 5, 1]]; min = [0.5, 1]; }", "    symmetry = x;\n"));
    ASSERT_TRUE(result.program.has_value()) << result.rendered();
    const auto& rules = result.program->grammars.at(0).rules;
    ASSERT_EQ(rules.size(), 2u);
    EXPECT_EQ(rules[1].aggregates.at(0).boxMin, glm::ivec3(2, 0, 0));
    EXPECT_EQ(rules[1].aggregates.at(0).boxMax, glm::ivec3(3, 5, 1));
}

TEST(check_Aggregates, AnAllIgnSymbolWithATestIsNotW0201) {
    const auto warnsW0201 = [](const CheckResult& result) {
        const Codes found = codes(result);
        return std::find(found.begin(), found.end(), "W0201") != found.end();
    };
    EXPECT_FALSE(warnsW0201(check(ruleWhere("where { mean = [0, 1]; }"))));
    EXPECT_TRUE(warnsW0201(check(ruleWhere(""))));
}

// A mean's bounds times the box's cells bound its sum as floats: a product past the largest float
// (3e38 * 15) is a located E0007 at the bound, not an infinite bound for the kernels to write;
// the largest bound whose product is a float passes, and its sum bound is finite.
TEST(check_Aggregates, MeanBoundsWhoseSumBoundIsNoFloatAreLocatedErrors) {
    const CheckResult tooLarge = check(ruleWhere("where { mean = [0, 3e38]; }"));
    EXPECT_EQ(codes(tooLarge), Codes{"E0007"});
    EXPECT_NE(tooLarge.rendered().find("test.vox:8:20: error E0007: 'mean' bounds lie in"), std::string::npos)
        << tooLarge.rendered();
    EXPECT_NE(tooLarge.rendered().find("15 cells"), std::string::npos) << tooLarge.rendered();
    EXPECT_EQ(codes(check(ruleWhere("where { mean = [-3e38, 0]; }"))), Codes{"E0007"});
    EXPECT_FALSE(check(ruleWhere("where { box = [[0, 0, 0], [1, 1, 1]]; mean = [0, 3e38]; }")).hasErrors());
    const double largest = double(std::numeric_limits<float>::max()) / 15.0 * (1.0 - 1e-12);
    const auto tests = testsOf(check(ruleWhere(fmt::format("where {{ mean = [-{0:.15f}e37, {0:.15f}e37]; }}", largest / 1e37))));
    ASSERT_EQ(tests.size(), 1u);
    EXPECT_TRUE(std::isfinite(tests[0].low) && std::isfinite(tests[0].high));
    EXPECT_EQ(tests[0].high, std::numeric_limits<float>::max());
    EXPECT_FALSE(check(ruleWhere("where { max = [0, 3e38]; }")).hasErrors()); // a value, not a sum
}

TEST(check_Aggregates, BadBlocksAreLocatedErrors) {
    EXPECT_EQ(codes(check(ruleWhere("where { mean = [0.8, 0.2]; }"))), Codes{"E0007"});
    EXPECT_EQ(codes(check(ruleWhere("where { solid_fraction = [0, 1.5]; }"))), Codes{"E0007"});
    EXPECT_EQ(codes(check(ruleWhere("where { box = [[0, 0, 0], [4, 1, 1]]; mean = [0, 1]; }"))), Codes{"E0007"});
    EXPECT_EQ(codes(check(ruleWhere("where { mean = 0.5; }"))), Codes{"E0010"});
    EXPECT_EQ(codes(check(ruleWhere("where { median = [0, 1]; }"))), Codes{"E0008"});
    EXPECT_EQ(codes(check(ruleWhere("where { }"))), Codes{"E0009"});
    EXPECT_EQ(codes(check(ruleWhere("where { material_fraction = [granite, 0, 1]; }"))), Codes{"E0002"});
    EXPECT_EQ(codes(check(ruleWhere("wher { mean = [0, 1]; }"))), Codes{"E0008"});
}

} // namespace aggregates_check_test
} // namespace voxc
