// renderSlice against a reviewed golden file. To regenerate after an intended change run
// tests/interp/update_golden.sh (sets VOXC_UPDATE_GOLDEN=1), then review the diff.
#include "ProgramText.h"
#include "voxc/core/Errors.h"
#include "voxc/interp/Slice.h"

#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <sstream>

namespace voxc {
namespace slice_test {

// Every density band on one z layer, plus a second layer to tell the axes apart.
DenseGrid bandGrid() {
    DenseGrid grid = test::gridFromRows({"0 0.1 0.25 0.5", "0.99 1 1.5 -0.5", "0 0 0 0", "---", "1 1 1 1",
                                         "0 0 0 0", "0.3 0.3 0.3 0.3"});
    grid.at({3, 0, 0}) = std::numeric_limits<float>::quiet_NaN();
    return grid;
}

std::string renderAll() {
    const DenseGrid grid = bandGrid();
    std::string out;
    out += renderSlice(grid, 2, 0) + "\n";
    out += renderSlice(grid, 2, 1) + "\n";
    out += renderSlice(grid, 1, 2) + "\n";
    out += renderSlice(grid, 0, 1);
    return out;
}

TEST(interp_Slice, MatchesGolden) {
    const std::string path = std::string(VOXC_INTERP_GOLDEN_DIR) + "/slices.txt";
    const std::string actual = renderAll();
    if (const char* update = std::getenv("VOXC_UPDATE_GOLDEN"); update && std::string(update) == "1") {
        std::ofstream(path, std::ios::binary) << actual;
        GTEST_SKIP() << "golden updated: " << path;
    }
    std::ifstream in(path, std::ios::binary);
    ASSERT_TRUE(in) << "missing golden " << path << "; run tests/interp/update_golden.sh";
    std::stringstream expected;
    expected << in.rdbuf();
    EXPECT_EQ(actual, expected.str());
}

TEST(interp_Slice, RowsRunFromTheTop) {
    const DenseGrid grid = test::gridFromRows({"1 0", "0 0"}); // (0,1) solid
    const std::string text = renderSlice(grid, 2, 0);
    EXPECT_NE(text.find("1 |# |\n0 |  |\n"), std::string::npos) << text;
}

TEST(interp_Slice, OutOfRangeIsAUserError) {
    const DenseGrid grid = bandGrid();
    EXPECT_THROW(renderSlice(grid, 3, 0), UserError);
    EXPECT_THROW(renderSlice(grid, 2, 2), UserError);
    EXPECT_THROW(renderSlice(grid, 0, -1), UserError);
}

} // namespace slice_test
} // namespace voxc
