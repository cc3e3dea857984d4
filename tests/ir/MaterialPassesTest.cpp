// The passes on material tests and writes: predicate bits number material tests after the
// density tests, dead-cells keeps the cells whose material alone is read or written, and
// remove-dead-stages keeps every stage that writes materials (and what it reads).
#include "SamplePrograms.h"
#include "voxc/ir/Lower.h"
#include "voxc/ir/passes/BuildSweeps.h"
#include "voxc/ir/passes/DeadCells.h"
#include "voxc/ir/passes/PredicateBits.h"
#include "voxc/ir/passes/RemoveDeadStages.h"
#include "voxc/stages/StageKind.h"

#include <gtest/gtest.h>

namespace voxc::ir {
namespace {

IrModule withCells(const Program& program) { return eliminateDeadCells(assignPredicateBits(buildSweeps(program))); }

// buildSweeps plus the fields, as lowerProgram copies them, from the program with its stages
// described again (the tests edit them).
IrModule built(Program program) {
    stages::describePipeline(program);
    IrModule module = buildSweeps(program);
    for (const Field& field : program.fields)
        module.fields.push_back(IrField{field.name, field.loc, field.nodes, field.root, {}});
    return module;
}

std::vector<std::string> stageNames(const std::vector<Stage>& stages) {
    std::vector<std::string> names;
    for (const Stage& stage : stages) names.push_back(printStage(stage));
    return names;
}

TEST(ir_PredicateBits, MaterialTestsFollowTheDensityTests) {
    const IrModule m = withCells(test::materialProgram());
    // Sweep 1 ([1,2,1]): sand_on_top (bottom GEQ 0.5 & MAT 1, top LT 0.5) and erode_sand
    // (bottom GEQ 0.5 & MAT 2, top ABS & NMAT 3).
    const IrSweep& sweep = m.grammars.at(0).sweeps.at(1);
    const IrCell& bottom = sweep.cells.at(0);
    ASSERT_EQ(bottom.tests.size(), 1u);
    EXPECT_EQ(bottom.tests[0].op, SymbolOp::GEQ);
    ASSERT_EQ(bottom.materialTests.size(), 2u);
    EXPECT_EQ(bottom.materialTests[0].material, 1);
    EXPECT_EQ(bottom.materialTests[1].material, 2);
    EXPECT_EQ(testCount(bottom), 3u);
    const IrCell& top = sweep.cells.at(1);
    EXPECT_EQ(top.tests.size(), 2u);
    ASSERT_EQ(top.materialTests.size(), 1u);
    EXPECT_EQ(top.materialTests[0].op, MaterialOp::NMAT);
    const IrRule& sand = sweep.rules.at(0);
    const IrRule& erode = sweep.rules.at(1);
    EXPECT_EQ(sand.needs[0], (std::vector<uint32_t>{0, 1}));
    EXPECT_EQ(erode.needs[0], (std::vector<uint32_t>{0, 2}));
    EXPECT_EQ(sand.needs[1], (std::vector<uint32_t>{0}));
    EXPECT_EQ(erode.needs[1], (std::vector<uint32_t>{1, 2}));
}

TEST(ir_DeadCells, KeepsCellsWhoseMaterialAloneIsUsed) {
    const IrModule m = withCells(test::materialProgram());
    // Sweep 0 ([2,1,1]) spread_moss: cell 0 only MAT 3 (no density read), cell 1 GEQ 0.5 & NMAT 3 -> MAT 3.
    const IrSweep& spread = m.grammars.at(0).sweeps.at(0);
    EXPECT_EQ(spread.cells[0].access, CellAccess::Address);
    EXPECT_TRUE(spread.cells[0].loadsMaterial);
    EXPECT_EQ(spread.cells[1].access, CellAccess::Load);
    EXPECT_TRUE(spread.cells[1].loadsMaterial);
    // Without its material test, cell 0 is neither read nor written.
    Program program = test::materialProgram();
    program.grammars[0].rules[0].symbol[0].materialPredicates.clear();
    const IrModule withoutTest = withCells(program);
    const IrCell& cell = withoutTest.grammars.at(0).sweeps.at(0).cells[0];
    EXPECT_EQ(cell.access, CellAccess::None);
    EXPECT_FALSE(cell.loadsMaterial);
    // A transform cell that only writes a material needs the address alone.
    program.grammars[0].rules[0].symbol[1] = SymbolCell{};
    const IrModule writeOnly = withCells(program);
    const IrCell& written = writeOnly.grammars.at(0).sweeps.at(0).cells[1];
    EXPECT_EQ(written.access, CellAccess::Address);
    EXPECT_FALSE(written.loadsMaterial);
}

TEST(ir_RemoveDeadStages, KeepsStagesThatWriteMaterials) {
    // start (materials), intersect slope, set low material moss, weather, paint half: only the
    // intersect is dead (it writes no material and the set overwrites its densities).
    const IrModule m = removeDeadStages(built(test::materialProgram(true)));
    EXPECT_EQ(stageNames(m.deadStages), (std::vector<std::string>{"intersect slope"}));
    EXPECT_EQ(stageNames(m.pipeline), (std::vector<std::string>{"start", "set low material 3", "weather",
                                                                     "paint half material 1"}));
}

TEST(ir_RemoveDeadStages, DropsStagesWhenNothingBeforeTheSetWritesMaterials) {
    Program program = test::materialProgram(true);
    for (StartShape& shape : program.start) shape.material.reset();
    const IrModule m = removeDeadStages(built(program));
    EXPECT_EQ(stageNames(m.deadStages), (std::vector<std::string>{"start", "intersect slope"}));
}

TEST(ir_RemoveDeadStages, KeepsWhatAMaterialWriterReads) {
    Program program = test::materialProgram(true);
    for (StartShape& shape : program.start) shape.material.reset();
    const Stage start = program.pipeline[0], intersect = program.pipeline[1], set = program.pipeline[2],
                weather = program.pipeline[3];
    Stage setPlain = set;
    setPlain.material.reset();
    // weather writes materials from the densities of start and intersect: all are kept.
    program.pipeline = {start, intersect, weather, setPlain};
    IrModule m = removeDeadStages(built(program));
    EXPECT_TRUE(m.deadStages.empty());
    // A field stage with a material is kept; the density-only stage after it is not.
    Stage unionMoss = intersect;
    unionMoss.mode = FieldMode::Union;
    unionMoss.material = 3;
    program.pipeline = {start, unionMoss, intersect, setPlain};
    m = removeDeadStages(built(program));
    EXPECT_EQ(stageNames(m.deadStages), (std::vector<std::string>{"intersect slope"}));
    EXPECT_EQ(stageNames(m.pipeline), (std::vector<std::string>{"start", "union slope material 3", "set low"}));
}

TEST(ir_PrintIr, ShowsMaterials) {
    const std::string text = printIr(lowerProgram(test::materialProgram()));
    for (const char* piece : {"box value 1.0 material 1", "cell 0 (0, 0, 0) address material tests 0:MAT 3",
                              "(1, 0, 0) GEQ 0.5 & NMAT 3", "transform (1, 0, 0) MAT 3",
                              "(0, 1, 0) SET 0.5 & MAT 1", "pipeline start union half material 3 weather",
                              "paint half material 1"})
        EXPECT_NE(text.find(piece), std::string::npos) << piece << "\n" << text;
}

} // namespace
} // namespace voxc::ir
