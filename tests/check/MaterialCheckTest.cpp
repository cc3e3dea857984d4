// Materials in the checker: `material` blocks, MAT/NMAT cells, the `material` key of start
// shapes and features, and pipeline material clauses (docs/language.md, "Materials").
#include "CheckTestUtil.h"

#include <gtest/gtest.h>

namespace voxc {
namespace material_check_test {

using test::check;
using test::codes;
using Codes = std::vector<std::string>;

const std::string kWorld = "world { size = [16, 16, 16]; }\n";
const std::string kRockSand = "material rock { id = 7; color = [0.5, 0.25, 1]; }\nmaterial sand { }\n";

// A one-rule grammar over the rock and sand materials.
std::string rule(const std::string& size, const std::string& symbol, const std::string& transform) {
    return kWorld + kRockSand + "grammar g { rule r { size = " + size + "; symbol { " + symbol +
           " } transform { " + transform + " } } }\n";
}

TEST(check_Materials, DeclarationsIdsAndColors) {
    const CheckResult result = check(kWorld + kRockSand + "material clay { id = 255; }\n");
    ASSERT_TRUE(result.program) << result.rendered();
    const std::vector<Material>& materials = result.program->materials;
    ASSERT_EQ(materials.size(), 3u);
    EXPECT_EQ(materials[0].name, "rock");
    EXPECT_EQ(materials[0].id, 7);
    EXPECT_EQ(materials[0].color, glm::vec3(0.5f, 0.25f, 1.0f));
    EXPECT_EQ(materials[0].loc.line, 2u);
    EXPECT_EQ(materials[1].id, 2); // 1 + its index among the materials
    EXPECT_EQ(materials[1].color, glm::vec3(0.6f));
    EXPECT_EQ(materials[2].id, 255);
    // Declaring materials that nothing uses does not turn the channel on.
    EXPECT_FALSE(result.program->usesMaterials());
    EXPECT_TRUE(check(kWorld).program->materials.empty());
}

// The example of docs/language.md ("Materials").
TEST(check_Materials, DocumentedExample) {
    const CheckResult result = check(
        "world { size = [64, 64, 64]; }\n"
        "material rock { id = 1; color = [0.42, 0.40, 0.38]; }\n"
        "material sand { color = [0.86, 0.78, 0.55]; }\n"
        "start {\n  fill { value = 0; }\n  heightfield { base = 24; material = rock; }\n}\n"
        "field low = y < 20 ? 1 : 0;\n"
        "feature arch1 = arch { start = [8, 8, 8]; end = [40, 40, 8]; material = rock; }\n"
        "feature cave1 = cave { start = [16, 16, 4]; }\n"
        "grammar weather {\n  rule sand_on_top {\n    size = [1, 2, 1];\n"
        "    symbol { [LT 0.5] [GEQ 0.5 & MAT rock] }\n    transform { [NOP] [MAT sand] }\n  }\n}\n"
        "pipeline { start; union arch1; subtract cave1 material sand; paint low material rock; weather; }\n");
    ASSERT_TRUE(result.program) << result.rendered();
    EXPECT_TRUE(result.diagnostics.empty()) << result.rendered();
    const Program& program = *result.program;
    EXPECT_EQ(program.materials.at(1).id, 2);
    EXPECT_EQ(program.start.at(1).material, std::optional<uint8_t>(1));
    ASSERT_EQ(program.pipeline.size(), 5u);
    EXPECT_EQ(program.pipeline[1].material, std::optional<uint8_t>(1));
    EXPECT_EQ(program.pipeline[2].material, std::optional<uint8_t>(2));
    EXPECT_EQ(program.pipeline[3].mode, FieldMode::Paint);
    EXPECT_EQ(program.pipeline[4].kind, Stage::Kind::Grammar);
}

TEST(check_Materials, DeclarationErrors) {
    EXPECT_EQ(codes(check(kWorld + "material none { }")), Codes{"E0003"});
    EXPECT_EQ(codes(check(kWorld + "material a { }\nmaterial a { }")), Codes{"E0003"});
    EXPECT_EQ(codes(check(kWorld + "material a { id = 3; }\nmaterial b { id = 3; }")), Codes{"E0003"});
    // b's default id is 2 (second material), which a claims explicitly.
    const CheckResult defaultClash = check(kWorld + "material a { id = 2; }\nmaterial b { }");
    ASSERT_EQ(codes(defaultClash), Codes{"E0003"});
    EXPECT_EQ(defaultClash.diagnostics[0].loc.line, 3u);
    EXPECT_EQ(codes(check(kWorld + "material a { id = 0; }")), Codes{"E0007"});
    EXPECT_EQ(codes(check(kWorld + "material a { id = 256; }")), Codes{"E0007"});
    EXPECT_EQ(codes(check(kWorld + "material a { id = 1.5; }")), Codes{"E0010"});
    EXPECT_EQ(codes(check(kWorld + "material a { color = [0, 1.5, 0]; }")), Codes{"E0007"});
    EXPECT_EQ(codes(check(kWorld + "material a { color = 0.5; }")), Codes{"E0010"});
    EXPECT_EQ(codes(check(kWorld + "material a { colour = [0, 0, 0]; }")), Codes{"E0008"});
    EXPECT_EQ(codes(check(kWorld + "material { }")), Codes{"E0009"});
}

TEST(check_Materials, MoreThan255NeedExplicitIds) {
    std::string text = kWorld;
    for (int i = 0; i < 256; ++i) text += "material m" + std::to_string(i) + " { }\n";
    EXPECT_EQ(codes(check(text)), Codes{"E0012"});
}

TEST(check_Materials, SymbolCellTests) {
    const CheckResult result = check(rule("[3, 1, 1]", "[GEQ 0.5 & MAT rock, NMAT none, MAT sand & NMAT rock]",
                                          "[NOP, NOP, NOP]"));
    ASSERT_TRUE(result.program) << result.rendered();
    const std::vector<SymbolCell>& cells = result.program->grammars[0].rules[0].symbol;
    ASSERT_EQ(cells[0].predicates.size(), 1u);
    ASSERT_EQ(cells[0].materialPredicates.size(), 1u);
    EXPECT_EQ(cells[0].materialPredicates[0].op, MaterialOp::MAT);
    EXPECT_EQ(cells[0].materialPredicates[0].material, 7);
    EXPECT_TRUE(cells[1].predicates.empty());
    EXPECT_EQ(cells[1].materialPredicates[0].op, MaterialOp::NMAT);
    EXPECT_EQ(cells[1].materialPredicates[0].material, kMaterialNone);
    ASSERT_EQ(cells[2].materialPredicates.size(), 2u);
    EXPECT_EQ(cells[2].materialPredicates[1].op, MaterialOp::NMAT);
    EXPECT_TRUE(result.program->usesMaterials());
    EXPECT_TRUE(result.diagnostics.empty()) << result.rendered(); // a MAT-only cell is not IGN (W0201)
}

TEST(check_Materials, TransformCellWrites) {
    const CheckResult result = check(rule("[4, 1, 1]", "[PRES, PRES, PRES, PRES]",
                                          "[MAT sand, SET 1 & MAT rock, MAT none & ADD -0.5, NOP & MAT sand]"));
    ASSERT_TRUE(result.program) << result.rendered();
    const std::vector<TransformCell>& cells = result.program->grammars[0].rules[0].transform;
    EXPECT_EQ(cells[0].op, TransformOp::NOP);
    EXPECT_EQ(cells[0].material, std::optional<uint8_t>(2));
    EXPECT_EQ(cells[1].op, TransformOp::SET);
    EXPECT_EQ(cells[1].value, 1.0f);
    EXPECT_EQ(cells[1].material, std::optional<uint8_t>(7));
    EXPECT_EQ(cells[2].op, TransformOp::ADD);
    EXPECT_EQ(cells[2].value, -0.5f);
    EXPECT_EQ(cells[2].material, std::optional<uint8_t>(kMaterialNone));
    EXPECT_EQ(cells[3].op, TransformOp::NOP);
    EXPECT_EQ(cells[3].material, std::optional<uint8_t>(2));
    EXPECT_TRUE(result.program->usesMaterials());
    EXPECT_FALSE(check(rule("[1, 1, 1]", "[PRES]", "[SET 1]")).program->grammars[0].rules[0].transform[0].material);
}

TEST(check_Materials, CellErrors) {
    EXPECT_EQ(codes(check(rule("[1, 1, 1]", "[MAT]", "[NOP]"))), Codes{"E0006"});
    EXPECT_EQ(codes(check(rule("[1, 1, 1]", "[PRES]", "[MAT]"))), Codes{"E0006"});
    EXPECT_EQ(codes(check(rule("[1, 1, 1]", "[NMAT 3]", "[NOP]"))), Codes{"E0010"});
    EXPECT_EQ(codes(check(rule("[1, 1, 1]", "[PRES]", "[MAT 1]"))), Codes{"E0010"});
    const CheckResult typo = check(rule("[1, 1, 1]", "[MAT rokc]", "[NOP]"));
    ASSERT_EQ(codes(typo), Codes{"E0002"});
    EXPECT_NE(typo.diagnostics[0].message.find("did you mean 'rock'"), std::string::npos) << typo.rendered();
    EXPECT_EQ(codes(check(rule("[1, 1, 1]", "[PRES]", "[MAT rock & MAT sand]"))), Codes{"E0003"});
    EXPECT_EQ(codes(check(rule("[1, 1, 1]", "[PRES]", "[NMAT rock]"))), Codes{"E0011"});
    EXPECT_EQ(codes(check(rule("[1, 1, 1]", "[PRES]", "[SET 1 & ADD 1]"))), Codes{"E0006"});
    // Material names are their own namespace: a constant is not a material.
    EXPECT_EQ(codes(check("const rocky = 1;\n" + rule("[1, 1, 1]", "[MAT rocky]", "[NOP]"))), Codes{"E0002"});
}

TEST(check_Materials, StartShapesTakeAMaterialKey) {
    const CheckResult result = check(kWorld + kRockSand +
                                     "start { fill { value = 0; } box { min = [0, 0, 0]; max = [4, 4, 4]; "
                                     "material = rock; } heightfield { material = none; } }");
    ASSERT_TRUE(result.program) << result.rendered();
    const std::vector<StartShape>& shapes = result.program->start;
    ASSERT_EQ(shapes.size(), 3u);
    EXPECT_FALSE(shapes[0].material);
    EXPECT_EQ(shapes[1].material, std::optional<uint8_t>(7));
    EXPECT_EQ(shapes[1].max, glm::vec3(4.0f));
    EXPECT_EQ(shapes[2].material, std::optional<uint8_t>(kMaterialNone));
    EXPECT_TRUE(result.program->usesMaterials());

    EXPECT_EQ(codes(check(kWorld + "start { fill { material = rock; } }")), Codes{"E0002"});
    EXPECT_EQ(codes(check(kWorld + kRockSand + "start { fill { material = 1; } }")), Codes{"E0010"});
    EXPECT_EQ(codes(check(kWorld + kRockSand + "start { fill { material = [rock]; } }")), Codes{"E0010"});
    EXPECT_EQ(codes(check(kWorld + kRockSand + "start { fill { material = rock; material = sand; } }")),
              Codes{"E0003"});
}

TEST(check_Materials, PipelineClausesAndFeatureKeys) {
    const CheckResult result = check(
        kWorld + kRockSand + "field low = y < 4 ? 1 : 0;\n" +
        "feature a = arch { start = [2, 2, 2]; end = [12, 2, 2]; material = sand; }\n"
        "feature c = cave { }\n"
        "pipeline { start; union a; subtract a material rock; set low; paint low material none; union c; }");
    ASSERT_TRUE(result.program) << result.rendered();
    const std::vector<Stage>& stages = result.program->pipeline;
    ASSERT_EQ(stages.size(), 6u);
    EXPECT_EQ(stages[1].material, std::optional<uint8_t>(2)); // the feature's key
    EXPECT_EQ(stages[2].material, std::optional<uint8_t>(7)); // the clause overrides it
    EXPECT_FALSE(stages[3].material);
    EXPECT_EQ(stages[4].mode, FieldMode::Paint);
    EXPECT_EQ(stages[4].material, std::optional<uint8_t>(kMaterialNone));
    EXPECT_FALSE(stages[5].material);
    EXPECT_FALSE(stages[0].material);
    EXPECT_TRUE(result.program->usesMaterials());
}

TEST(check_Materials, PipelineErrors) {
    const std::string decls = kWorld + kRockSand + "field low = y < 4 ? 1 : 0;\ngrammar g { rule r { size = [1, 1, 1]; "
                                                   "symbol { [PRES] } transform { [NOP] } } }\n";
    EXPECT_EQ(codes(check(decls + "pipeline { start; paint low; }")), Codes{"E0009"});
    EXPECT_EQ(codes(check(decls + "pipeline { start; set low material rokc; }")), Codes{"E0002"});
    EXPECT_EQ(codes(check(decls + "pipeline { start; set low materal rock; }")), Codes{"E0008"});
    EXPECT_EQ(codes(check(decls + "pipeline { start; set low material; }")), Codes{"E0009"});
    EXPECT_EQ(codes(check(decls + "pipeline { start; g material rock; }")), Codes{"E0010"});
    EXPECT_EQ(codes(check(decls + "pipeline { start material rock; g; }")), Codes{"E0010"});
    EXPECT_EQ(codes(check(decls + "pipeline { start; paint g material rock; }")), Codes{"E0010"});
    EXPECT_EQ(codes(check(decls + "feature a = cave { material = granite; }")), Codes{"E0002"});
    EXPECT_EQ(codes(check(decls + "feature a = cave { material = 2; }")), Codes{"E0010"});
}

TEST(check_Materials, ContradictoryTestsNeverMatch) {
    EXPECT_EQ(codes(check(rule("[1, 1, 1]", "[MAT rock & MAT sand]", "[NOP]"))), Codes{"W0202"});
    EXPECT_EQ(codes(check(rule("[1, 1, 1]", "[MAT rock & NMAT rock & NMAT sand]", "[NOP]"))), Codes{"W0202"});
    EXPECT_EQ(codes(check(rule("[1, 1, 1]", "[MAT rock & MAT rock & NMAT sand]", "[NOP]"))), Codes{});
    const CheckResult message = check(rule("[1, 1, 1]", "[PRES & MAT rock & MAT sand]", "[NOP]"));
    ASSERT_EQ(codes(message), Codes{"W0202"});
    EXPECT_NE(message.diagnostics[0].message.find("no material passes"), std::string::npos) << message.rendered();
}

TEST(check_Materials, DifferentMaterialTestsSeparateEqualPriorityRules) {
    const std::string head = kWorld + kRockSand + "grammar g {\n";
    const std::string a = "rule a { size = [1, 1, 1]; symbol { [PRES & MAT rock] } transform { [NOP] } }\n";
    const std::string b = "rule b { size = [1, 1, 1]; symbol { [PRES & MAT sand] } transform { [NOP] } }\n";
    const std::string c = "rule c { size = [1, 1, 1]; symbol { [PRES & NMAT sand] } transform { [NOP] } }\n";
    EXPECT_EQ(codes(check(head + a + b + "}")), Codes{});
    EXPECT_EQ(codes(check(head + a + c + "}")), Codes{"W0203"});
}

} // namespace material_check_test
} // namespace voxc
