// The printed layout (first row = top, columns along +x, layers from lowest z) against
// Program's cell order (cellIndex: x fastest, then y up, then z).
#include "CheckTestUtil.h"

#include <gtest/gtest.h>

namespace voxc {
namespace layout_test {

using test::check;
using test::oneRule;

const Rule& onlyRule(const CheckResult& result) {
    EXPECT_TRUE(result.program.has_value()) << result.rendered();
    return result.program->grammars.at(0).rules.at(0);
}

// Dey Fig 3.2 prints its input voxels as [0.0 0.0 0.5] / [0.5 0.0 0.5] / [0.9 0.9 0.5], top
// to bottom. Written as a symbol of EQ tests, the top printed row must land at y = 2.
TEST(check_Layout, Fig32RowsTopToBottom) {
    CheckResult result = check(oneRule("[3, 3, 1]",
                                       "[EQ 0.0, EQ 0.0, EQ 0.5] [EQ 0.5, EQ 0.0, EQ 0.5] [EQ 0.9, EQ 0.9, EQ 0.5]",
                                       "[ADD 0.2, SET 0.5, NOP] [ADD -0.2, NOP, NOP] [SET 0.5, NOP, NOP]"));
    const Rule& rule = onlyRule(result);
    const glm::ivec3 size = rule.size;
    const float printed[3][3] = {{0.0f, 0.0f, 0.5f}, {0.5f, 0.0f, 0.5f}, {0.9f, 0.9f, 0.5f}};
    for (int row = 0; row < 3; ++row)
        for (int x = 0; x < 3; ++x) {
            const SymbolCell& cell = rule.symbol[cellIndex(size, x, 2 - row, 0)];
            ASSERT_EQ(cell.predicates.size(), 1u);
            EXPECT_EQ(cell.predicates[0].op, SymbolOp::EQ);
            EXPECT_EQ(cell.predicates[0].value, printed[row][x]) << "row " << row << " column " << x;
        }
    // Bottom-left voxel (x = 0, y = 0) is the last printed row's first cell: 0.9 / SET 0.5.
    EXPECT_EQ(rule.symbol[0].predicates[0].value, 0.9f);
    EXPECT_EQ(rule.transform[0].op, TransformOp::SET);
    EXPECT_EQ(rule.transform[0].value, 0.5f);
    // Top-left (x = 0, y = 2) is the first printed row's first cell: ADD 0.2.
    EXPECT_EQ(rule.transform[cellIndex(size, 0, 2, 0)].op, TransformOp::ADD);
    EXPECT_EQ(rule.transform[cellIndex(size, 0, 2, 0)].value, 0.2f);
    // Top-middle: SET 0.5; middle-left: ADD -0.2.
    EXPECT_EQ(rule.transform[cellIndex(size, 1, 2, 0)].op, TransformOp::SET);
    EXPECT_EQ(rule.transform[cellIndex(size, 0, 1, 0)].value, -0.2f);
}

TEST(check_Layout, LayersRunFromLowestZ) {
    CheckResult result = check(oneRule("[2, 1, 2]", "layer { [EQ 1, EQ 2] } layer { [EQ 3, EQ 4] }",
                                       "layer { [NOP, NOP] } layer { [SET 5, NOP] }"));
    const Rule& rule = onlyRule(result);
    EXPECT_EQ(rule.symbol[cellIndex(rule.size, 0, 0, 0)].predicates[0].value, 1.0f);
    EXPECT_EQ(rule.symbol[cellIndex(rule.size, 1, 0, 0)].predicates[0].value, 2.0f);
    EXPECT_EQ(rule.symbol[cellIndex(rule.size, 0, 0, 1)].predicates[0].value, 3.0f);
    EXPECT_EQ(rule.symbol[cellIndex(rule.size, 1, 0, 1)].predicates[0].value, 4.0f);
    EXPECT_EQ(rule.transform[cellIndex(rule.size, 0, 0, 1)].op, TransformOp::SET);
}

TEST(check_Layout, ThreeDimensionalWindow) {
    // [2, 2, 2]: printed rows per layer are top first, so layer 2's first row is (y = 1, z = 1).
    CheckResult result = check(oneRule("[2, 2, 2]", "layer { [EQ 1, EQ 2] [EQ 3, EQ 4] } layer { [EQ 5, EQ 6] [EQ 7, EQ 8] }",
                                       "layer { [NOP, NOP] [NOP, NOP] } layer { [NOP, NOP] [NOP, NOP] }"));
    const Rule& rule = onlyRule(result);
    auto value = [&](int x, int y, int z) { return rule.symbol[cellIndex(rule.size, x, y, z)].predicates[0].value; };
    EXPECT_EQ(value(0, 1, 0), 1.0f);
    EXPECT_EQ(value(1, 0, 0), 4.0f);
    EXPECT_EQ(value(0, 1, 1), 5.0f);
    EXPECT_EQ(value(1, 0, 1), 8.0f);
}

TEST(check_Layout, IgnIsAnEmptyPredicateListAndConjunctionsKeepOrder) {
    CheckResult result = check(oneRule("[2, 1, 1]", "[IGN, GEQ 0.25 & LT 0.75 & NEQ 0.5]", "[NOP, NOP]"));
    const Rule& rule = onlyRule(result);
    EXPECT_TRUE(rule.symbol[0].predicates.empty());
    ASSERT_EQ(rule.symbol[1].predicates.size(), 3u);
    EXPECT_EQ(rule.symbol[1].predicates[0].op, SymbolOp::GEQ);
    EXPECT_EQ(rule.symbol[1].predicates[1].op, SymbolOp::LT);
    EXPECT_EQ(rule.symbol[1].predicates[2].op, SymbolOp::NEQ);
    EXPECT_EQ(rule.symbol[1].predicates[2].value, 0.5f);
}

TEST(check_Layout, ShapeErrors) {
    EXPECT_EQ(test::codes(check(oneRule("[2, 2, 1]", "[PRES, PRES]", "[NOP, NOP] [NOP, NOP]"))),
              std::vector<std::string>{"E0004"});
    EXPECT_EQ(test::codes(check(oneRule("[2, 1, 1]", "[PRES]", "[NOP, NOP]"))), std::vector<std::string>{"E0004"});
    EXPECT_EQ(test::codes(check(oneRule("[1, 1, 2]", "[PRES]", "layer { [NOP] } layer { [NOP] }"))),
              std::vector<std::string>{"E0004"});
    EXPECT_EQ(test::codes(check(oneRule("[2, 2, 1]", "[PRES, PRES] [PRES]", "[NOP, NOP] [NOP, NOP]"))),
              std::vector<std::string>{"E0005"});
    EXPECT_EQ(test::codes(check(oneRule("[1, 2, 2]", "layer { [PRES] [PRES] } layer { [PRES] }",
                                        "layer { [NOP] [NOP] } layer { [NOP] [NOP] }"))),
              std::vector<std::string>{"E0005"});
}

} // namespace layout_test
} // namespace voxc
