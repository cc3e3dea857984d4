// W0201-W0204: warnings never stop the program from being produced.
#include "CheckTestUtil.h"

#include <gtest/gtest.h>

namespace voxc {
namespace analyses_test {

using test::check;
using test::codes;
using test::oneRule;
using Codes = std::vector<std::string>;

TEST(check_Analyses, AllIgnore) {
    CheckResult result = check(oneRule("[2, 1, 1]", "[IGN, IGN]", "[SET 1, NOP]"));
    EXPECT_EQ(codes(result), Codes{"W0201"});
    EXPECT_TRUE(result.program.has_value());
    EXPECT_FALSE(result.hasErrors());
}

TEST(check_Analyses, EmptyIntersectionNamesThePrintedCell) {
    CheckResult result = check(oneRule("[2, 2, 1]", "[PRES, IGN] [IGN, EQ 0.5 & NEQ 0.5]", "[NOP, NOP] [NOP, NOP]"));
    ASSERT_EQ(codes(result), Codes{"W0202"});
    EXPECT_NE(result.diagnostics[0].message.find("row 2, column 2"), std::string::npos) << result.rendered();
    EXPECT_TRUE(result.program.has_value());
    // ABS and GT 0 exclude each other; GEQ 0 and LEQ 0 meet at exactly 0 (exact comparisons).
    EXPECT_EQ(codes(check(oneRule("[1, 1, 1]", "[ABS & GT 0]", "[NOP]"))), Codes{"W0202"});
    EXPECT_EQ(codes(check(oneRule("[1, 1, 1]", "[GEQ 0 & LEQ 0]", "[NOP]"))), Codes{});
}

TEST(check_Analyses, OverlappingEqualPriorityRules) {
    auto twoRules = [](const std::string& first, const std::string& second, const std::string& extra) {
        return "world { size = [8, 8, 8]; }\ngrammar g {\n"
               "  rule a { size = [2, 1, 1]; symbol { " + first + " } transform { [NOP, NOP] } }\n"
               "  rule b { size = [2, 1, 1]; " + extra + " symbol { " + second + " } transform { [NOP, NOP] } }\n}";
    };
    CheckResult overlap = check(twoRules("[GEQ 0.5, IGN]", "[GT 0.7, LT 1]", ""));
    ASSERT_EQ(codes(overlap), Codes{"W0203"});
    EXPECT_EQ(overlap.diagnostics[0].notes.size(), 1u);
    EXPECT_NE(overlap.diagnostics[0].message.find("weights decide"), std::string::npos);
    EXPECT_EQ(codes(check(twoRules("[GEQ 0.5, IGN]", "[LT 0.5, IGN]", ""))), Codes{});
    EXPECT_EQ(codes(check(twoRules("[GEQ 0.5, IGN]", "[GEQ 0.5, IGN]", "priority = 1;"))), Codes{});
    // Touching intervals: LEQ 0.5 and GEQ 0.5 share exactly 0.5.
    EXPECT_EQ(codes(check(twoRules("[LEQ 0.5, IGN]", "[GEQ 0.5, IGN]", ""))), Codes{"W0203"});
    EXPECT_EQ(codes(check(twoRules("[LT 0.5, IGN]", "[GEQ 0.5, IGN]", ""))), Codes{});
}

TEST(check_Analyses, WindowLargerThanBounds) {
    CheckResult result = check(oneRule("[3, 1, 1]", "[PRES, PRES, PRES]", "[NOP, NOP, NOP]", "",
                                       "bounds = [[0, 0, 0], [2, 16, 16]];"));
    EXPECT_EQ(codes(result), Codes{"W0204"});
    EXPECT_TRUE(result.program.has_value());
}

TEST(check_Analyses, NoWarningsWhenThereAreErrors) {
    CheckResult result = check("world { size = [8, 8, 8]; chunk = 7; }\n" +
                               test::withoutWorld(oneRule("[1, 1, 1]", "[IGN]", "[NOP]")));
    EXPECT_EQ(codes(result), Codes{"E0007"});
}

} // namespace analyses_test
} // namespace voxc
