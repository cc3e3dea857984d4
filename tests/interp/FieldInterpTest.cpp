// Field stages in the interpreter: every node kind evaluates through the registry, inputs at a
// non-zero origin, let sharing, inlining, each FieldMode and the pipeline order with grammars.
#include "CheckedProgram.h"
#include "voxc/check/Check.h"
#include "voxc/interp/FieldEval.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/program/Semantics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace voxc {
namespace field_interp_test {

Program checked(const std::string& text) { return test::checkedProgram("test.vox", text); }

// The value of the program's last field at one voxel.
float fieldAt(const std::string& world, const std::string& declarations, glm::ivec3 voxel) {
    const Program program = checked(world + declarations);
    if (program.fields.empty()) return NAN;
    FieldEvaluator evaluator(program.fields.back(), program.world.origin);
    return evaluator.density(voxel);
}

const std::string kWorld = "world { size = [8, 8, 8]; origin = [100, -20, 3]; }\n";

TEST(interp_Fields, InputsAreLocalIndicesAndWorldCoordinates) {
    const glm::ivec3 v{1, 2, 5};
    EXPECT_EQ(fieldAt(kWorld, "field f = x * 100 + y * 10 + z;", v), 125.0f);
    EXPECT_EQ(fieldAt(kWorld, "field f = wx;", v), 101.0f);
    EXPECT_EQ(fieldAt(kWorld, "field f = wy;", v), -18.0f);
    EXPECT_EQ(fieldAt(kWorld, "field f = wz;", v), 8.0f);
    EXPECT_EQ(fieldAt(kWorld, "field f = dot(wp - p, vec3(1, 1, 1));", v), 83.0f);
}

TEST(interp_Fields, EveryNodeKindEvaluates) {
    const glm::ivec3 v{3, 4, 0};
    EXPECT_EQ(fieldAt(kWorld, "field f = 0.5;", v), 0.5f);                             // Constant
    EXPECT_EQ(fieldAt(kWorld, "field f = (p * 2).y;", v), 8.0f);                       // Component of a Call
    EXPECT_EQ(fieldAt(kWorld, "field f = length(p.xy);", v), 5.0f);                    // vec2 swizzle
    EXPECT_EQ(fieldAt(kWorld, "field f = -x / 2 - 1;", v), -2.5f);                     // neg, div, sub
    EXPECT_EQ(fieldAt(kWorld, "field f = x < 4 && !(y == 3) ? 1 : 0;", v), 1.0f);      // logic, select
    EXPECT_EQ(fieldAt(kWorld, "field f = x >= 4 || y != 4 ? 1 : 0;", v), 0.0f);
    EXPECT_EQ(fieldAt(kWorld, "field f = clamp(mix(x, y, 0.5), 0, 1);", v), 1.0f);     // math builtins
    EXPECT_EQ(fieldAt(kWorld, "field f = perlin3(vec3(wx, wy, wz) * 0.1, 7);", v),
              functions()[size_t(findFunction("perlin3") - functions().data())]
                  .eval(std::vector<Value>{Value::makeVec3(glm::vec3(103, -16, 3) * 0.1f), Value::makeInt(7)})
                  .v.x);
}

TEST(interp_Fields, LetAndInlinedFunctionsEvaluateAsWritten) {
    const glm::ivec3 v{2, 3, 4};
    EXPECT_EQ(fieldAt(kWorld, "field f = let h = x + y in h * h;", v), 25.0f);
    EXPECT_EQ(fieldAt(kWorld, "field f = let x = 10 in x + z;", v), 14.0f); // a let shadows an input
    EXPECT_EQ(fieldAt(kWorld, "fn sq(v: float) -> float = v * v;\nfn f2(a: vec3) -> float = sq(a.x) + sq(a.z);\n"
                              "field f = f2(p);",
                      v),
              20.0f);
}

TEST(interp_Fields, ModesCombineWithTheDensity) {
    const auto density = [](FieldMode mode, float d, float f) { return combineField(mode, std::nullopt, f, {d, 0}).density; };
    EXPECT_EQ(density(FieldMode::Set, 0.3f, 0.7f), 0.7f);
    EXPECT_EQ(density(FieldMode::Union, 0.3f, 0.7f), 0.7f);
    EXPECT_EQ(density(FieldMode::Union, 0.9f, 0.7f), 0.9f);
    EXPECT_EQ(density(FieldMode::Subtract, 0.9f, 0.25f), 0.75f);
    EXPECT_EQ(density(FieldMode::Subtract, 0.5f, 0.25f), 0.5f);
    EXPECT_EQ(density(FieldMode::Intersect, 0.9f, 0.25f), 0.25f);
    EXPECT_EQ(density(FieldMode::Intersect, 0.1f, 0.25f), 0.1f);
    EXPECT_EQ(density(FieldMode::Paint, 0.1f, 1.0f), 0.1f);
}

// A stage's material lands where the field wins and the voxel ends solid (Semantics.h).
TEST(interp_Fields, MaterialsLandWhereTheFieldWinsAndTheVoxelEndsSolid) {
    static constexpr uint8_t kOld = 3, kNew = 7;
    const auto material = [](FieldMode mode, float d, float f) { return combineField(mode, kNew, f, {d, kOld}).material; };
    EXPECT_EQ(material(FieldMode::Set, 0.0f, 0.7f), kNew);
    EXPECT_EQ(material(FieldMode::Set, 1.0f, 0.2f), kOld);        // ends air
    EXPECT_EQ(material(FieldMode::Union, 0.3f, 0.7f), kNew);
    EXPECT_EQ(material(FieldMode::Union, 0.9f, 0.7f), kOld);      // the rock was there already
    EXPECT_EQ(material(FieldMode::Union, 0.7f, 0.7f), kOld);      // a tie is no win
    EXPECT_EQ(material(FieldMode::Subtract, 1.0f, 0.25f), kNew);  // the cave's ramp: still rock, now lined
    EXPECT_EQ(material(FieldMode::Subtract, 1.0f, 0.9f), kOld);   // carved to air
    EXPECT_EQ(material(FieldMode::Subtract, 0.5f, 0.25f), kOld);  // 0.75 does not beat 0.5
    EXPECT_EQ(material(FieldMode::Intersect, 0.9f, 0.6f), kNew);
    EXPECT_EQ(material(FieldMode::Intersect, 0.9f, 0.4f), kOld);  // ends air
    EXPECT_EQ(material(FieldMode::Paint, 0.5f, 0.5f), kNew);
    EXPECT_EQ(material(FieldMode::Paint, 0.4f, 1.0f), kOld);      // air is not painted
    EXPECT_EQ(material(FieldMode::Paint, 1.0f, 0.4f), kOld);
    EXPECT_EQ(combineField(FieldMode::Union, std::nullopt, 0.9f, {0.0f, kOld}).material, kOld);
}

// start (box x < 4) -> set/union/subtract/intersect fields -> a grammar that sees the result.
TEST(interp_Fields, PipelineRunsStagesInOrder) {
    const std::string world = "world { size = [8, 1, 1]; }\nstart { box { min = [0, 0, 0]; max = [4, 1, 1]; } }\n";
    const std::string fields = "field ramp = x / 8;\nfield half = 0.5;\nfield right = x >= 6 ? 1 : 0;\n";
    const std::string grammar =
        "grammar bump { rule r { size = [1, 1, 1]; symbol { [EQ 0.5] } transform { [ADD 0.25] } } }\n";
    auto run = [&](const std::string& pipeline) {
        const DenseGrid grid = interpret(checked(world + fields + grammar + pipeline));
        std::vector<float> row;
        for (int x = 0; x < 8; ++x) row.push_back(grid.at({x, 0, 0}));
        return row;
    };
    using Row = std::vector<float>;
    EXPECT_EQ(run("pipeline { start; set ramp; }"), (Row{0, 0.125f, 0.25f, 0.375f, 0.5f, 0.625f, 0.75f, 0.875f}));
    EXPECT_EQ(run("pipeline { start; union ramp; }"), (Row{1, 1, 1, 1, 0.5f, 0.625f, 0.75f, 0.875f}));
    EXPECT_EQ(run("pipeline { start; subtract ramp; }"), (Row{1, 0.875f, 0.75f, 0.625f, 0, 0, 0, 0}));
    EXPECT_EQ(run("pipeline { start; intersect half; }"), (Row{0.5f, 0.5f, 0.5f, 0.5f, 0, 0, 0, 0}));
    // The grammar sees what the field stage wrote, and a later stage sees the grammar's result.
    EXPECT_EQ(run("pipeline { start; intersect half; bump; union right; }"),
              (Row{0.75f, 0.75f, 0.75f, 0.75f, 0, 0, 1, 1}));
    EXPECT_EQ(run("pipeline { start; bump; intersect half; }"), (Row{0.5f, 0.5f, 0.5f, 0.5f, 0, 0, 0, 0}));
}

TEST(interp_Fields, ExampleRunsAndCarvesTheTunnel) {
    CheckResult result = checkFile(std::string(VOXC_EXAMPLES_DIR) + "/fields.vox");
    ASSERT_TRUE(result.program) << result.rendered();
    EXPECT_TRUE(result.diagnostics.empty()) << result.rendered();
    const DenseGrid grid = interpret(*result.program);
    EXPECT_EQ(grid.at({0, 0, 0}), 1.0f);    // deep ground
    EXPECT_EQ(grid.at({0, 63, 0}), 0.0f);   // sky
    EXPECT_EQ(grid.at({32, 19, 32}), 0.0f); // the tunnel's axis passes near here
    EXPECT_EQ(grid.at({44, 45, 16}), 1.0f); // the pillar rises above the ground
}

} // namespace field_interp_test
} // namespace voxc
