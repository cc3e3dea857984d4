// Each pass is shown to fire on the sample program: counts before and after, and the
// pieces of IR text it changes.
#include "SamplePrograms.h"
#include "voxc/ir/passes/BuildSweeps.h"
#include "voxc/ir/passes/DeadCells.h"
#include "voxc/ir/passes/PredicateBits.h"
#include "voxc/ir/passes/RemoveNeverMatchingRules.h"
#include "voxc/program/Semantics.h"

#include <gtest/gtest.h>

namespace voxc::ir {
namespace {

const IrSweep& sweepOf(const IrModule& m, size_t grammar, size_t sweep) {
    return m.grammars.at(grammar).sweeps.at(sweep);
}

std::vector<uint32_t> ruleIndices(const IrSweep& sweep) {
    std::vector<uint32_t> out;
    for (const IrRule& r : sweep.rules)
        out.push_back(r.ruleIndex);
    return out;
}

TEST(ir_BuildSweeps, GroupsRulesInExecutionOrder) {
    const Program program = test::sampleProgram();
    const IrModule m = buildSweeps(program);
    ASSERT_EQ(m.grammars.size(), 2u);
    for (size_t g = 0; g < m.grammars.size(); ++g) {
        const std::vector<Sweep> expected = orderSweeps(program.grammars[g]);
        ASSERT_EQ(m.grammars[g].sweeps.size(), expected.size());
        for (size_t s = 0; s < expected.size(); ++s) {
            const IrSweep& sweep = sweepOf(m, g, s);
            EXPECT_EQ(sweep.index, s);
            EXPECT_EQ(sweep.window, expected[s].window);
            EXPECT_EQ(sweep.anchorCount, expected[s].anchorCount);
            EXPECT_EQ(sweep.phaseCount, expected[s].phaseCount);
            EXPECT_EQ(ruleIndices(sweep), expected[s].rules);
            EXPECT_EQ(sweep.cells.size(), size_t(sweep.window.x * sweep.window.y * sweep.window.z));
        }
    }
    // "smooth" declares the [1,1,1] rule first, but the larger [2,1,2] window runs first.
    EXPECT_EQ(sweepOf(m, 1, 0).window, glm::ivec3(2, 1, 2));
    EXPECT_EQ(ruleIndices(sweepOf(m, 1, 0)), std::vector<uint32_t>{1});
    // Cells are in cellIndex order: x fastest, then y, then z.
    EXPECT_EQ(sweepOf(m, 1, 0).cells[2].offset, glm::ivec3(0, 0, 1));
    EXPECT_EQ(sweepOf(m, 0, 0).cells[5].offset, glm::ivec3(2, 1, 0));
}

TEST(ir_RemoveNeverMatchingRules, DropsRulesWithAnImpossibleCell) {
    const IrModule before = buildSweeps(test::sampleProgram());
    const IrModule after = removeNeverMatchingRules(before);
    EXPECT_EQ(ruleIndices(sweepOf(before, 0, 0)), (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_EQ(ruleIndices(sweepOf(after, 0, 0)), (std::vector<uint32_t>{0, 1}));
    ASSERT_EQ(sweepOf(after, 0, 0).removed.size(), 1u);
    EXPECT_EQ(sweepOf(after, 0, 0).removed[0].ruleIndex, 2u);
    EXPECT_EQ(sweepOf(after, 0, 0).removed[0].name, "never");
    EXPECT_EQ(sweepOf(after, 0, 0).cells[sweepOf(after, 0, 0).removed[0].cell].offset, glm::ivec3(1, 1, 0));
    // A sweep may lose every rule; its kernel then does nothing.
    EXPECT_TRUE(sweepOf(after, 1, 1).rules.empty());
    EXPECT_EQ(sweepOf(after, 1, 1).removed.at(0).name, "impossible");
    // Rules that can match keep their stable indices.
    EXPECT_EQ(ruleIndices(sweepOf(after, 0, 1)), std::vector<uint32_t>{3});
    EXPECT_NE(printIr(before), printIr(after));
    EXPECT_NE(printIr(after).find("removed rule 2 never (28:3): cell 4 passes no density"), std::string::npos);
}

TEST(ir_PredicateBits, SharesEachDistinctPredicateOfACell) {
    const IrModule m = assignPredicateBits(removeNeverMatchingRules(buildSweeps(test::sampleProgram())));
    const IrSweep& sweep = sweepOf(m, 0, 0);
    // Cell (0,0,0): both rules test GEQ 0.5, which becomes one bit.
    ASSERT_EQ(sweep.cells[0].tests.size(), 1u);
    EXPECT_EQ(sweep.cells[0].tests[0].op, SymbolOp::GEQ);
    EXPECT_EQ(sweep.rules[0].needs[0], std::vector<uint32_t>{0});
    EXPECT_EQ(sweep.rules[1].needs[0], std::vector<uint32_t>{0});
    // Cell (1,0,0): erode needs LT 0.5 & GT 0.1, grow needs LT 0.5 only: two bits, shared LT.
    ASSERT_EQ(sweep.cells[1].tests.size(), 2u);
    EXPECT_EQ(sweep.rules[0].needs[1], (std::vector<uint32_t>{0, 1}));
    EXPECT_EQ(sweep.rules[1].needs[1], std::vector<uint32_t>{0});
    // Cell (1,2,0) is IGN for grow: it needs no bits there.
    EXPECT_TRUE(sweep.rules[1].needs[7].empty());
    size_t predicates = 0, bits = 0;
    for (const IrRule& r : sweep.rules)
        for (const SymbolCell& c : r.symbol)
            predicates += c.predicates.size();
    for (const IrCell& c : sweep.cells)
        bits += c.tests.size();
    EXPECT_EQ(predicates, 13u);
    EXPECT_EQ(bits, 8u);
    // The all-IGN rule of "smooth" needs nothing at all.
    for (const std::vector<uint32_t>& needs : sweepOf(m, 1, 0).rules[0].needs)
        EXPECT_TRUE(needs.empty());
}

TEST(ir_DeadCells, LoadsOnlyWhatTheLiveRulesUse) {
    const IrModule before = assignPredicateBits(removeNeverMatchingRules(buildSweeps(test::sampleProgram())));
    const IrModule after = eliminateDeadCells(before);
    for (const IrCell& c : sweepOf(before, 0, 0).cells)
        EXPECT_EQ(c.access, CellAccess::Load);
    const std::vector<IrCell>& cells = sweepOf(after, 0, 0).cells;
    EXPECT_EQ(cells[0].access, CellAccess::Load); // read (and ADD)
    EXPECT_EQ(cells[2].access, CellAccess::Load); // ABS read, ADD write
    EXPECT_EQ(cells[4].access, CellAccess::Load); // read by both, SET by grow
    EXPECT_EQ(cells[5].access, CellAccess::None); // IGN and NOP in every rule
    EXPECT_EQ(cells[8].access, CellAccess::None); // only the removed rule wrote it
    const std::vector<IrCell>& blend = sweepOf(after, 1, 0).cells;
    EXPECT_EQ(blend[0].access, CellAccess::None);
    EXPECT_EQ(blend[1].access, CellAccess::Load);    // ADD needs the old density
    EXPECT_EQ(blend[2].access, CellAccess::Address); // SET only writes
    EXPECT_EQ(blend[3].access, CellAccess::None);
    // The never-matching sweep touches nothing.
    EXPECT_EQ(sweepOf(after, 1, 1).cells[0].access, CellAccess::None);
}

} // namespace
} // namespace voxc::ir
