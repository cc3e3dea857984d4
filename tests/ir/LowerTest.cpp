#include "SamplePrograms.h"
#include "voxc/ir/Lower.h"

#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace voxc::ir {
namespace {

TEST(ir_Lower, ReportsEveryPassInOrder) {
    std::vector<std::string> names;
    std::vector<std::string> texts;
    LowerOptions options;
    options.afterPass = [&](std::string_view name, const IrModule& m) {
        names.emplace_back(name);
        texts.push_back(printIr(m));
    };
    const IrModule m = lowerProgram(test::sampleProgram(), options);
    EXPECT_EQ(names, (std::vector<std::string>{"build-sweeps", "remove-dead-stages", "remove-never-matching-rules",
                                               "predicate-bits", "dead-cells", "fold-constants",
                                               "eliminate-common-subexpressions", "hoist-column-values"}));
    // Every grammar pass changes the sample program's IR (it has no fields and no `set`; the
    // field passes are shown to fire in FieldPassesTest.cpp); the last text is the result.
    for (size_t i = 2; i < 5; ++i)
        EXPECT_NE(texts[i - 1], texts[i]) << names[i];
    EXPECT_EQ(texts.back(), printIr(m));
}

TEST(ir_Lower, PrintIsStable) {
    const Program program = test::sampleProgram();
    EXPECT_EQ(printIr(lowerProgram(program)), printIr(lowerProgram(program)));
}

TEST(ir_Lower, PrintShowsTheLoweredRule) {
    const std::string text = printIr(lowerProgram(test::sampleProgram()));
    EXPECT_NE(
        text.find(
            "grammar overhang (8:1) stride [1, 1, 1] bounds [0, 0, 0]..[20, 12, 10] iterations 4 clamp [0.0, 1.0]"),
        std::string::npos)
        << text;
    EXPECT_NE(text.find("    rule 1 grow (20:3) priority 1 weight 500 probability 12582912\n"), std::string::npos)
        << text;
    EXPECT_NE(text.find("    cell 1 (1, 0, 0) load tests 0:LT 0.5 1:GT 0.100000001\n"), std::string::npos) << text;
}

} // namespace
} // namespace voxc::ir
