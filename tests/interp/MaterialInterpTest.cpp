// The material channel in the interpreter: start shapes write their material where they are
// inside, rules test it with MAT/NMAT and write it with `MAT m`, field stages follow combineField.
#include "ProgramText.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/stages/Pipeline.h"

#include <gtest/gtest.h>

namespace voxc {
namespace material_interp_test {

using test::gridFromRows;
using test::makeGrammar;
using test::makeProgram;
using test::makeRule;

constexpr uint8_t kRock = 1, kSand = 2;

std::vector<int> materialRow(const DenseGrid& grid) {
    std::vector<int> row;
    for (int x = 0; x < grid.size().x; ++x) row.push_back(grid.materialAt({x, 0, 0}));
    return row;
}

TEST(interp_Materials, StartShapesWriteTheirMaterialWhereTheyAreInside) {
    Program program = makeProgram({6, 1, 1}, {});
    StartShape fill{ShapeKind::Fill};
    fill.value = 0.0f;
    StartShape rock{ShapeKind::Box};
    rock.min = {0, 0, 0}, rock.max = {4, 1, 1}, rock.material = kRock;
    StartShape plain{ShapeKind::Box}; // no material: densities change, materials do not
    plain.min = {3, 0, 0}, plain.max = {5, 1, 1}, plain.value = 0.5f;
    program.start = {fill, rock, plain};
    const DenseGrid grid = evaluateStart(program);
    EXPECT_EQ(materialRow(grid), (std::vector<int>{1, 1, 1, 1, 0, 0}));
    EXPECT_EQ(grid.at({3, 0, 0}), 0.5f);
    EXPECT_EQ(grid.at({2, 0, 0}), 1.0f);
}

TEST(interp_Materials, RulesTestAndWriteMaterials) {
    // Sand settles on rock: a solid rock voxel with air above turns to sand; NMAT keeps sand from
    // matching itself and a rule writing only a material leaves the density alone.
    Grammar weather = makeGrammar("weather", {}, {makeRule("top", {"LT 0.5", "GEQ 0.5 & MAT 1"}, {"NOP", "MAT 2"})});
    DenseGrid grid = gridFromRows({"0 0 0", "1 1 0.7"}); // printed: first row is the top (y = 1)
    grid.materialAt({0, 0, 0}) = kRock, grid.materialAt({1, 0, 0}) = kSand, grid.materialAt({2, 0, 0}) = kRock;
    weather.boundsMax = grid.size();
    const Program program = makeProgram(grid.size(), {weather});
    runGrammar(program, 0, grid);
    EXPECT_EQ(materialRow(grid), (std::vector<int>{kSand, kSand, kSand}));
    EXPECT_EQ(grid.at({2, 0, 0}), 0.7f);

    DenseGrid mixed = gridFromRows({"1 1 1"});
    Grammar strip = makeGrammar("strip", mixed.size(), {makeRule("r", {"NMAT 2"}, {"SET 0 & MAT 0"})});
    mixed.materialAt({1, 0, 0}) = kSand;
    runGrammar(makeProgram(mixed.size(), {strip}), 0, mixed);
    EXPECT_EQ(materialRow(mixed), (std::vector<int>{0, kSand, 0}));
    EXPECT_EQ(mixed.at({0, 0, 0}), 0.0f);
    EXPECT_EQ(mixed.at({1, 0, 0}), 1.0f);
}

TEST(interp_Materials, FieldStagesPaintWhereTheFieldWins) {
    Program program = makeProgram({6, 1, 1}, {});
    StartShape rock{ShapeKind::Box};
    rock.min = {0, 0, 0}, rock.max = {3, 1, 1}, rock.material = kRock;
    program.start = {rock};
    Field half; // f = 0.75 everywhere
    half.name = "half";
    FieldNode c;
    c.constant = glm::vec3(0.75f);
    half.nodes = {c};
    program.fields = {half};
    program.pipeline.push_back({Stage::Kind::Field, 0, FieldMode::Union, {}, kSand});
    const DenseGrid unioned = interpret(program);
    // Union with 0.75 wins over the air (0) at x >= 3, not over the rock (1).
    EXPECT_EQ(materialRow(unioned), (std::vector<int>{kRock, kRock, kRock, kSand, kSand, kSand}));

    program.pipeline.back() = {Stage::Kind::Field, 0, FieldMode::Paint, {}, kSand};
    const DenseGrid painted = interpret(program);
    // Paint keeps densities and paints only the solid voxels.
    EXPECT_EQ(materialRow(painted), (std::vector<int>{kSand, kSand, kSand, 0, 0, 0}));
    EXPECT_EQ(painted.at({4, 0, 0}), 0.0f);
}

} // namespace material_interp_test
} // namespace voxc
