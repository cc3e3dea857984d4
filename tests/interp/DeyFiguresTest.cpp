// Dey, ch. 3, Figures 3.1 and 3.2, run through the interpreter on the figures' 3x3 input.
//
// Fig 3.1's extracted text prints only two operators per symbol row, while its input and its
// per-cell result marks have three columns: one column of operators is lost. The marks decide
// which: symbol 2's crosses fall at (row 1, col 3), (row 2, col 2), (row 3, col 2), which are
// exactly the cells where ABS meets 0.5, PRES meets 0.0 and GT 0.9 meets 0.9 when the printed
// operators are the *second and third* columns. So the lost column is the first one; it passes
// everywhere (inputs 0.0, 0.5, 0.9), and we read it as IGN. LT 1.0 there gives the same results.
#include "ProgramText.h"
#include "voxc/builtins/Ops.h"
#include "voxc/interp/Interpreter.h"

#include <gtest/gtest.h>

namespace voxc {
namespace dey_figures_test {

using test::gridFromRows;
using test::makeGrammar;
using test::makeProgram;
using test::makeRule;

const std::vector<std::string> kInput = {"0.0 0.0 0.5", "0.5 0.0 0.5", "0.9 0.9 0.5"};

// Number of times a single-rule grammar fires on the figure's input.
int firings(const Rule& rule) {
    const Program program = makeProgram({3, 3, 1}, {makeGrammar("fig", {3, 3, 1}, {rule})});
    DenseGrid grid = gridFromRows(kInput);
    int fired = 0;
    runGrammar(program, 0, grid, InterpOptions{[&](const TraceEvent&) { ++fired; }});
    return fired;
}

Rule withAllNop(const char* name, std::vector<std::string> symbol) {
    return makeRule(name, symbol, {"NOP, NOP, NOP", "NOP, NOP, NOP", "NOP, NOP, NOP"});
}

const std::vector<std::string> kSymbol1 = {"IGN, ABS, LT 1.0", "IGN, ABS, LT 1.0", "IGN, GEQ 0.8, LT 1.0"};
const std::vector<std::string> kSymbol2 = {"IGN, ABS, ABS", "IGN, PRES, LT 1.0", "IGN, GT 0.9, LT 1.0"};

// The figure's per-cell marks as printed rows ('v' pass, 'x' fail).
std::vector<std::string> marks(const Rule& rule) {
    const DenseGrid input = gridFromRows(kInput);
    std::vector<std::string> rows;
    for (int y = 2; y >= 0; --y) {
        std::string row;
        for (int x = 0; x < 3; ++x)
            row += cellPasses(rule.symbol[size_t(cellIndex(rule.size, x, y, 0))], input.at({x, y, 0}), kMaterialNone) ? 'v' : 'x';
        rows.push_back(row);
    }
    return rows;
}

std::vector<std::string> withFirstColumn(std::vector<std::string> rows, const std::string& op) {
    for (std::string& row : rows) row.replace(0, 3, op);
    return rows;
}

TEST(interp_Dey, Figure31FirstSymbolPasses) {
    EXPECT_EQ(marks(withAllNop("s1", kSymbol1)), (std::vector<std::string>{"vvv", "vvv", "vvv"}));
    EXPECT_EQ(firings(withAllNop("s1", kSymbol1)), 1);
    EXPECT_EQ(firings(withAllNop("s1", withFirstColumn(kSymbol1, "LT 1.0"))), 1);
}

TEST(interp_Dey, Figure31SecondSymbolFails) {
    // The crosses where the figure prints them; GT 0.9 fails on 0.9 (strict, exact comparison).
    EXPECT_EQ(marks(withAllNop("s2", kSymbol2)), (std::vector<std::string>{"vvx", "vxv", "vxv"}));
    EXPECT_EQ(firings(withAllNop("s2", kSymbol2)), 0);
    EXPECT_EQ(firings(withAllNop("s2", withFirstColumn(kSymbol2, "LT 1.0"))), 0);
}

TEST(interp_Dey, Figure32Transform) {
    const Rule rule = makeRule("t", {"IGN, IGN, IGN", "IGN, IGN, IGN", "IGN, IGN, IGN"},
                               {"ADD 0.2, SET 0.5, NOP", "ADD -0.2, NOP, NOP", "SET 0.5, NOP, NOP"});
    const Program program = makeProgram({3, 3, 1}, {makeGrammar("fig", {3, 3, 1}, {rule})});
    DenseGrid grid = gridFromRows(kInput);
    runGrammar(program, 0, grid);
    // Thesis result [0.2 0.5 0.5]/[0.3 0.0 0.5]/[0.5 0.9 0.5], exactly as float arithmetic gives it.
    const float expected[3][3] = {{0.0f + 0.2f, 0.5f, 0.5f}, {0.5f - 0.2f, 0.0f, 0.5f}, {0.5f, 0.9f, 0.5f}};
    for (int row = 0; row < 3; ++row)
        for (int x = 0; x < 3; ++x) EXPECT_EQ(grid.at({x, 2 - row, 0}), expected[row][x]) << "row " << row << " x " << x;
    EXPECT_EQ(test::gridRows(grid), (std::vector<std::string>{"0.2 0.5 0.5", "0.3 0 0.5", "0.5 0.9 0.5"}));
}

} // namespace dey_figures_test
} // namespace voxc
