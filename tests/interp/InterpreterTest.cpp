// The interpreter's deterministic order: stride, bounds, phases, sweeps, priority, iterations,
// clamping, the pipeline and the start state.
#include "ProgramText.h"
#include "voxc/builtins/Shapes.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/stages/Pipeline.h"

#include <gtest/gtest.h>

namespace voxc {
namespace interpreter_test {

using test::gridFromRows;
using test::gridRows;
using test::makeGrammar;
using test::makeProgram;
using test::makeRule;

// Runs one grammar over a grid given as printed rows; returns the printed result.
std::vector<std::string> run(Grammar grammar, const std::vector<std::string>& rows, uint32_t seed = 0) {
    DenseGrid grid = gridFromRows(rows);
    if (grammar.boundsMax == glm::ivec3(0)) grammar.boundsMax = grid.size();
    const Program program = makeProgram(grid.size(), {std::move(grammar)}, seed);
    runGrammar(program, 0, grid);
    return gridRows(grid);
}

using Rows = std::vector<std::string>;

TEST(interp_Interpreter, StrideSkipsAnchors) {
    Grammar g = makeGrammar("g", {}, {makeRule("mark", {"IGN"}, {"ADD 1"})});
    g.stride = {3, 1, 1};
    EXPECT_EQ(run(g, {"0 0 0 0 0 0 0 0"}), Rows{"1 0 0 1 0 0 1 0"});
    Grammar wide = makeGrammar("g", {}, {makeRule("mark", {"IGN, IGN"}, {"ADD 1, ADD 1"})});
    wide.stride = {3, 1, 1};
    EXPECT_EQ(run(wide, {"0 0 0 0 0 0 0 0"}), Rows{"1 1 0 1 1 0 1 1"});
}

// A stride smaller than the window makes windows overlap across phases: each voxel is
// written once per window covering it.
TEST(interp_Interpreter, OverlappingWindowsAccumulateAcrossPhases) {
    Grammar g = makeGrammar("g", {}, {makeRule("mark", {"IGN, IGN, IGN"}, {"ADD 1, ADD 1, ADD 1"})});
    EXPECT_EQ(run(g, {"0 0 0 0 0 0"}), Rows{"1 2 3 3 2 1"});
}

TEST(interp_Interpreter, AnchorsOnlyWhereTheWindowFitsTheBounds) {
    Grammar g = makeGrammar("g", {}, {makeRule("mark", {"IGN, IGN"}, {"ADD 1, ADD 1"})});
    g.stride = {2, 1, 1};
    g.boundsMin = {2, 0, 0};
    g.boundsMax = {7, 1, 1};
    EXPECT_EQ(run(g, {"0 0 0 0 0 0 0 0"}), Rows{"0 0 1 1 1 1 0 0"});
}

TEST(interp_Interpreter, BoundsApplyOnEveryAxis) {
    Grammar g = makeGrammar("g", {}, {makeRule("mark", {"IGN"}, {"SET 1"})});
    g.boundsMin = {1, 1, 1};
    g.boundsMax = {3, 2, 2};
    EXPECT_EQ(run(g, {"0 0 0", "0 0 0", "---", "0 0 0", "0 0 0", "---", "0 0 0", "0 0 0"}),
              (Rows{"0 0 0", "0 0 0", "---", "0 1 1", "0 0 0", "---", "0 0 0", "0 0 0"}));
}

TEST(interp_Interpreter, WindowLargerThanBoundsNeverFires) {
    Grammar g = makeGrammar("g", {}, {makeRule("mark", {"IGN, IGN, IGN"}, {"SET 1, SET 1, SET 1"})});
    g.boundsMax = {2, 1, 1};
    EXPECT_EQ(run(g, {"0 0 0"}), Rows{"0 0 0"});
}

// Anchors 0 and 1 are in phases 0 and 1. Phase 0 first grows the solid into x=1, and phase 1
// then sees it and grows into x=2; the other order would stop at x=1.
TEST(interp_Interpreter, PhasesRunInOrderAndReadEarlierPhases) {
    Grammar g = makeGrammar("g", {}, {makeRule("grow", {"PRES, ABS"}, {"NOP, SET 1"})});
    EXPECT_EQ(run(g, {"1 0 0"}), Rows{"1 1 1"});
}

// Phase order is x fastest: with a 2x2 window on a 3x3 grid, phase 1 is the x-shifted anchor
// and phase 2 the y-shifted one. The rule copies a solid lower-left cell to its right and above
// when both are empty; running phase 2 before phase 1 would give top row "1 1 0" instead.
TEST(interp_Interpreter, PhasesRunXFastest) {
    Grammar g = makeGrammar("g", {}, {makeRule("spread", {"ABS, IGN", "PRES, ABS"}, {"SET 1, NOP", "NOP, SET 1"})});
    // Phase 0 anchor (0,0): fills (1,0),(0,1). Phase 1 anchor (1,0): lower-left (1,0) is solid,
    // (2,0) and (1,1) empty -> fills them. Phase 2 anchor (0,1): (0,1) solid, (1,1) is no longer
    // empty, so no match. Phase 3 anchor (1,1): fills (2,1) and (1,2).
    EXPECT_EQ(run(g, {"0 0 0", "0 0 0", "1 0 0"}), (Rows{"0 1 0", "1 1 1", "1 1 1"}));
}

TEST(interp_Interpreter, LargestSweepFirst) {
    // The 1x1 rule is declared first but the 2x1 sweep runs before it.
    Grammar g = makeGrammar("g", {}, {makeRule("small", {"ABS"}, {"SET 0.5"}),
                                      makeRule("big", {"ABS, ABS"}, {"SET 1, SET 1"})});
    EXPECT_EQ(run(g, {"0 0"}), Rows{"1 1"});
}

TEST(interp_Interpreter, EqualVolumeSweepsInDeclarationOrder) {
    const Rule across = makeRule("across", {"ABS, ABS"}, {"SET 1, SET 1"});
    const Rule up = makeRule("up", {"ABS", "ABS"}, {"SET 0.5", "SET 0.5"});
    EXPECT_EQ(run(makeGrammar("g", {}, {across, up}), {"0 0", "0 0"}), (Rows{"1 1", "1 1"}));
    EXPECT_EQ(run(makeGrammar("g", {}, {up, across}), {"0 0", "0 0"}), (Rows{"0.5 0.5", "0.5 0.5"}));
}

TEST(interp_Interpreter, HigherPriorityWins) {
    Rule low = makeRule("low", {"IGN"}, {"SET 1"});
    Rule high = makeRule("high", {"IGN"}, {"SET 2"});
    high.priority = 1;
    test::setWeight(low, 1000.0f); // weight never beats priority
    test::setWeight(high, 0.001f);
    const Rows zeros(8, "0 0 0 0 0 0 0 0");
    EXPECT_EQ(run(makeGrammar("g", {}, {low, high}), zeros), Rows(8, "2 2 2 2 2 2 2 2"));
    EXPECT_EQ(run(makeGrammar("g", {}, {high, low}), zeros, 99), Rows(8, "2 2 2 2 2 2 2 2"));
}

TEST(interp_Interpreter, LowerPriorityFiresWhereHigherDoesNotMatch) {
    Rule low = makeRule("low", {"IGN"}, {"SET 1"});
    Rule high = makeRule("high", {"PRES"}, {"SET 2"});
    high.priority = 3;
    EXPECT_EQ(run(makeGrammar("g", {}, {low, high}), {"0 0.5 0 0.5"}), Rows{"1 2 1 2"});
}

TEST(interp_Interpreter, IterationsRepeatTheGrammar) {
    Grammar add = makeGrammar("g", {}, {makeRule("add", {"IGN"}, {"ADD 1"})});
    add.iterations = 5;
    EXPECT_EQ(run(add, {"0 0 0"}), Rows{"5 5 5"});
    // Each iteration grows two voxels: one per phase.
    Grammar grow = makeGrammar("g", {}, {makeRule("grow", {"PRES, ABS"}, {"NOP, SET 1"})});
    grow.iterations = 3;
    EXPECT_EQ(run(grow, {"1 0 0 0 0 0 0 0"}), Rows{"1 1 1 1 1 1 1 0"});
}

TEST(interp_Interpreter, NoImplicitClamp) {
    Grammar g = makeGrammar("g", {}, {makeRule("add", {"IGN, IGN"}, {"ADD 0.75, ADD -0.75"})});
    EXPECT_EQ(run(g, {"0.5 0.5"}), Rows{"1.25 -0.25"});
}

TEST(interp_Interpreter, GrammarClampAppliesToWrittenCellsOnly) {
    Grammar g = makeGrammar("g", {}, {makeRule("add", {"IGN, IGN, IGN"}, {"ADD 0.75, ADD -0.75, NOP"})});
    g.clampMin = 0.0f;
    g.clampMax = 1.0f;
    EXPECT_EQ(run(g, {"0.5 0.5 7"}), Rows{"1 0 7"});
}

TEST(interp_Interpreter, ThreeDimensionalWindowUsesCellIndexOrder) {
    // Layer z=0 then z=1; the rule moves a voxel from the bottom layer's corner to the top layer's
    // opposite corner, so a wrong cell order would show up as a misplaced write.
    const Rule r = makeRule("move", {"PRES, IGN", "IGN, IGN", "---", "IGN, IGN", "IGN, ABS"},
                            {"SET 0, NOP", "NOP, NOP", "---", "NOP, NOP", "NOP, SET 1"});
    EXPECT_EQ(run(makeGrammar("g", {}, {r}), {"1 0", "0 0", "---", "0 0", "0 0"}),
              (Rows{"0 0", "0 0", "---", "0 0", "0 1"}));
}

TEST(interp_Interpreter, PipelineRunsGrammarsInItsOrder) {
    const Grammar fill = makeGrammar("fill", {4, 1, 1}, {makeRule("fill", {"IGN"}, {"SET 1"})});
    const Grammar bump = makeGrammar("bump", {4, 1, 1}, {makeRule("bump", {"EQ 1"}, {"SET 2"})});
    Program program = makeProgram({4, 1, 1}, {fill, bump});
    EXPECT_EQ(gridRows(interpret(program)), Rows{"2 2 2 2"});
    program.pipeline = {{Stage::Kind::Start, 0, FieldMode::Set, {}}, {Stage::Kind::Grammar, 1, FieldMode::Set, {}}, {Stage::Kind::Grammar, 0, FieldMode::Set, {}}};
    EXPECT_EQ(gridRows(interpret(program)), Rows{"1 1 1 1"});
    // A start stage after a grammar resets the grid to the start state.
    program.pipeline = {{Stage::Kind::Grammar, 0, FieldMode::Set, {}}, {Stage::Kind::Start, 0, FieldMode::Set, {}}, {Stage::Kind::Grammar, 1, FieldMode::Set, {}}};
    EXPECT_EQ(gridRows(interpret(program)), Rows{"0 0 0 0"});
}

TEST(interp_Interpreter, EmptyStartIsAir) {
    const Program program = makeProgram({3, 2, 2}, {});
    const DenseGrid grid = evaluateStart(program);
    EXPECT_EQ(grid.size(), glm::ivec3(3, 2, 2));
    for (float d : grid.data()) EXPECT_EQ(d, 0.0f);
}

TEST(interp_Interpreter, StartShapesInOrder) {
    Program program = makeProgram({6, 5, 4}, {});
    program.world.origin = {-100, 3, 1 << 20};
    StartShape fill;
    fill.kind = ShapeKind::Fill;
    fill.value = 0.25f;
    StartShape box;
    box.kind = ShapeKind::Box;
    box.min = {1, 1, 1};
    box.max = {3, 4, 2};
    box.value = 1.0f;
    StartShape ground;
    ground.kind = ShapeKind::Heightfield;
    ground.heightfield.base = 1.0f; // height stays within 1 +- 0.5: covers y=0 only
    ground.heightfield.amplitude = 0.25f;
    ground.value = 0.75f;
    program.start = {fill, box, ground};
    const DenseGrid grid = evaluateStart(program);
    EXPECT_EQ(grid.at({0, 4, 0}), 0.25f); // fill only
    EXPECT_EQ(grid.at({5, 0, 3}), 0.75f); // under the ground
    EXPECT_EQ(grid.at({2, 3, 1}), 1.0f);  // inside the box, above the ground
    EXPECT_EQ(grid.at({3, 3, 1}), 0.25f); // box max is exclusive
    for (int z = 0; z < 4; ++z)
        for (int y = 0; y < 5; ++y)
            for (int x = 0; x < 6; ++x) EXPECT_EQ(grid.at({x, y, z}), startVoxel(program, {x, y, z}).density);
    // The Start stage of the pipeline is exactly evaluateStart.
    EXPECT_EQ(interpret(program).data(), grid.data());
}

} // namespace interpreter_test
} // namespace voxc
