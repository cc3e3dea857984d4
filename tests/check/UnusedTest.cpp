// W0206-W0208: declarations the pipeline never uses are warnings at the declaration; anything a
// stage runs, or a shape, rule or stage clause tests or writes, counts as used.
#include "CheckTestUtil.h"

#include <gtest/gtest.h>

namespace voxc {
namespace unused_test {

using test::codes;
using Codes = std::vector<std::string>;

const std::string kHead = "world { size = [8, 8, 8]; }\n"
                          "material rock { }\nmaterial sand { }\nmaterial clay { }\nmaterial loam { }\n"
                          "field f = x;\nfield unused = y;\n"
                          "feature arch1 = arch { start = [1, 4, 4]; end = [7, 4, 4]; }\n"
                          "grammar g { rule r { size = [1, 1, 1]; symbol { [PRES & MAT sand] } transform { [NOP] } } }\n"
                          "grammar idle { rule r { size = [1, 1, 1]; symbol { [PRES] } transform { [NOP & MAT clay] } } }\n"
                          "start { fill { value = 1; material = rock; } }\n"
                          "material silt { }\n";

TEST(check_Unused, EachUnusedDeclarationIsReportedWhereItIsDeclared) {
    CheckResult result = test::check(kHead + "pipeline { start; g; union f material loam; }\n");
    ASSERT_EQ(codes(result), (Codes{"W0206", "W0206", "W0207", "W0208"})) << result.rendered();
    EXPECT_EQ(result.diagnostics[0].loc.line, 7u); // field unused
    EXPECT_EQ(result.diagnostics[1].loc.line, 8u); // feature arch1
    EXPECT_EQ(result.diagnostics[1].loc.column, 9u);
    EXPECT_EQ(result.diagnostics[2].loc.line, 10u); // grammar idle
    EXPECT_EQ(result.diagnostics[2].loc.column, 9u);
    // clay counts as used: a rule writes it, although its grammar does not run (W0207 says so).
    EXPECT_EQ(result.diagnostics[3].loc.line, 12u);
    EXPECT_NE(result.diagnostics[3].message.find("material 'silt' is never used"), std::string::npos);
}

TEST(check_Unused, UsingEverythingWarnsNothing) {
    CheckResult result =
        test::check(kHead + "pipeline { start; g; idle; union f material loam; set unused; paint arch1 material silt; }\n");
    EXPECT_EQ(codes(result), Codes{}) << result.rendered();
}

} // namespace unused_test
} // namespace voxc
