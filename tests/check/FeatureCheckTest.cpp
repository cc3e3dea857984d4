// `feature` blocks in the checker: the generator registry's key discipline and names.
#include "CheckTestUtil.h"

#include <gtest/gtest.h>

namespace voxc {
namespace feature_check_test {

using test::check;
using test::codes;
using Codes = std::vector<std::string>;

const std::string kWorld = "world { size = [64, 64, 64]; }\n";

TEST(check_Features, DefaultsCheckAndBecomeFields) {
    const CheckResult result = check(kWorld + "feature a = arch { }\nfeature c = cave { }\n"
                                     "feature o = overhang { min = [0, 0, 0]; max = [8, 8, 8]; }\n"
                                     "pipeline { start; union a; subtract c; union o; }");
    ASSERT_FALSE(result.hasErrors()) << result.rendered();
    ASSERT_EQ(result.program->fields.size(), 3u);
    EXPECT_EQ(result.program->fields[0].name, "a");
    EXPECT_EQ(result.program->pipeline.size(), 4u);
}

TEST(check_Features, ErrorsAreLocatedAtTheValue) {
    const CheckResult result = check(kWorld + "feature a = arch {\n  radius = 11;\n}");
    ASSERT_EQ(codes(result), Codes{"E0007"});
    EXPECT_EQ(result.diagnostics[0].loc.line, 3u);
}

TEST(check_Features, KeyDiscipline) {
    EXPECT_EQ(codes(check(kWorld + "feature a = arch { iterations = 60; }")), Codes{"E0007"});
    EXPECT_EQ(codes(check(kWorld + "feature a = arch { iterations = 20.5; }")), Codes{"E0010"});
    EXPECT_EQ(codes(check(kWorld + "feature a = cave { gravity_exponent = 0.5; }")), Codes{"E0007"});
    EXPECT_EQ(codes(check(kWorld + "feature a = cave { direction = [0, 0, 0]; }")), Codes{"E0007"});
    EXPECT_EQ(codes(check(kWorld + "feature a = arch { start = [1, 2, 3]; end = [1, 2, 3]; }")), Codes{"E0007"});
    EXPECT_EQ(codes(check(kWorld + "feature a = overhang { min = [0, 0, 0]; max = [8, 0, 8]; }")), Codes{"E0007"});
    EXPECT_EQ(codes(check(kWorld + "feature a = cave { mouht = 3; }")), Codes{"E0008"});
    EXPECT_EQ(codes(check(kWorld + "feature a = overhang { min = [0, 0, 0]; }")), Codes{"E0009"});
    EXPECT_EQ(codes(check(kWorld + "feature a = bridge { }")), Codes{"E0002"});
    EXPECT_EQ(codes(check(kWorld + "feature a = arch b { }")), Codes{"E0001"});
    EXPECT_EQ(codes(check(kWorld + "field a = 1;\nfeature a = arch { }")), Codes{"E0003"});
    EXPECT_EQ(codes(check(kWorld + "feature a = arch { }\nfeature a = cave { }")), Codes{"E0003"});
}

TEST(check_Features, ValuesOffTheThesisGridWarn) {
    const std::string pipeline = "pipeline { start; union a; }\n";
    EXPECT_EQ(codes(check(kWorld + "feature a = cave { mouth = 5.1; }\n" + pipeline)), Codes{"W0205"});
    EXPECT_EQ(codes(check(kWorld + "feature a = cave { mouth = 5.2; }\n" + pipeline)), Codes{});
    EXPECT_EQ(codes(check(kWorld + "feature a = arch { peak = 7; }\n" + pipeline)), Codes{"W0205"});
}

} // namespace feature_check_test
} // namespace voxc
