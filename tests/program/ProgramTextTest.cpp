// The test helper itself: printed layout (first row = top) maps to cellIndex order.
#include "ProgramText.h"

#include <gtest/gtest.h>

namespace voxc {
namespace {

TEST(program_ProgramText, FirstPrintedRowIsTop) {
    const Rule r = test::makeRule("r", {"EQ 1, EQ 2", "EQ 3, EQ 4"}, {"SET 1, NOP", "ADD -2, NOP"});
    EXPECT_EQ(r.size, glm::ivec3(2, 2, 1));
    EXPECT_EQ(r.symbol[size_t(cellIndex(r.size, 0, 1, 0))].predicates.at(0).value, 1.0f);
    EXPECT_EQ(r.symbol[size_t(cellIndex(r.size, 1, 1, 0))].predicates.at(0).value, 2.0f);
    EXPECT_EQ(r.symbol[size_t(cellIndex(r.size, 0, 0, 0))].predicates.at(0).value, 3.0f);
    EXPECT_EQ(r.transform[size_t(cellIndex(r.size, 0, 1, 0))].op, TransformOp::SET);
    EXPECT_EQ(r.transform[size_t(cellIndex(r.size, 0, 0, 0))].value, -2.0f);
}

TEST(program_ProgramText, LayersAreLowestZFirst) {
    const Rule r = test::makeRule("r", {"IGN", "---", "GT 0 & LT 1"}, {"NOP", "---", "SET 1"});
    EXPECT_EQ(r.size, glm::ivec3(1, 1, 2));
    EXPECT_TRUE(r.symbol[0].predicates.empty());
    EXPECT_EQ(r.symbol[1].predicates.size(), 2u);
    EXPECT_EQ(r.transform[1].op, TransformOp::SET);
}

TEST(program_ProgramText, GridRoundTrip) {
    const std::vector<std::string> rows = {"0 0 0.5", "0.5 0 0.5", "---", "1 2 3", "4 5 6"};
    const DenseGrid grid = test::gridFromRows(rows);
    EXPECT_EQ(grid.size(), glm::ivec3(3, 2, 2));
    EXPECT_EQ(grid.at({2, 1, 0}), 0.5f);
    EXPECT_EQ(grid.at({0, 0, 1}), 4.0f);
    EXPECT_EQ(test::gridRows(grid), rows);
}

TEST(program_ProgramText, MalformedTextThrows) {
    EXPECT_THROW(test::parseSymbolCell("LT"), std::invalid_argument);
    EXPECT_THROW(test::parseSymbolCell("ABS 0"), std::invalid_argument);
    EXPECT_THROW(test::parseTransformCell("MUL 2"), std::invalid_argument);
    EXPECT_THROW(test::makeRule("r", {"IGN, IGN", "IGN"}, {"NOP, NOP", "NOP"}), std::invalid_argument);
}

} // namespace
} // namespace voxc
