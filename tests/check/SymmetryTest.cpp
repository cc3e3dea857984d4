// `symmetry`: how many variants each group gives for asymmetric and symmetric windows, where
// cells move, variant names, and the errors and warnings of the key.
#include "CheckTestUtil.h"

#include <gtest/gtest.h>

namespace voxc {
namespace symmetry_test {

using test::check;
using test::codes;
using test::oneRule;
using Codes = std::vector<std::string>;

// A [3, 2, 2] window whose twelve cells all differ, so no rotation or reflection maps it to itself.
std::string asymmetricRule(const std::string& symmetry) {
    return oneRule("[3, 2, 2]",
                   "layer { [EQ 0.01, EQ 0.02, EQ 0.03] [EQ 0.04, EQ 0.05, EQ 0.06] } "
                   "layer { [EQ 0.07, EQ 0.08, EQ 0.09] [EQ 0.10, EQ 0.11, EQ 0.12] }",
                   "layer { [NOP, NOP, NOP] [SET 1, NOP, NOP] } layer { [NOP, NOP, NOP] [NOP, NOP, NOP] }",
                   "symmetry = " + symmetry + ";");
}

const Grammar& onlyGrammar(const CheckResult& result) {
    EXPECT_TRUE(result.program.has_value()) << result.rendered();
    return result.program->grammars.at(0);
}

TEST(check_Symmetry, VariantCountsOfAnAsymmetricWindow) {
    const std::pair<const char*, size_t> groups[] = {{"none", 1}, {"x", 2},      {"z", 2},      {"xz", 4},
                                                     {"rot_y", 4}, {"square", 8}, {"xyz", 8},    {"all", 48}};
    for (const auto& [group, count] : groups) {
        SCOPED_TRACE(group);
        EXPECT_EQ(onlyGrammar(check(asymmetricRule(group))).rules.size(), count);
    }
}

TEST(check_Symmetry, SymmetricWindowsDeduplicate) {
    // Mirror-symmetric in x: mirror_x gives the rule itself; a quarter turn gives the [1,1,3] shape.
    const std::string mirrored = "[PRES, ABS, PRES]";
    const std::pair<const char*, size_t> groups[] = {{"x", 1}, {"z", 1}, {"xz", 1}, {"rot_y", 2},
                                                     {"square", 2}, {"xyz", 1}, {"all", 3}};
    for (const auto& [group, count] : groups) {
        SCOPED_TRACE(group);
        const CheckResult result =
            check(oneRule("[3, 1, 1]", mirrored, "[NOP, SET 1, NOP]", std::string("symmetry = ") + group + ";"));
        EXPECT_EQ(onlyGrammar(result).rules.size(), count);
    }
    // A single cell is invariant under all 48 elements.
    EXPECT_EQ(onlyGrammar(check(oneRule("[1, 1, 1]", "[PRES]", "[ADD 1]", "symmetry = all;"))).rules.size(), 1u);
}

TEST(check_Symmetry, WindowsRotateWithTheRule) {
    const CheckResult result = check(asymmetricRule("rot_y"));
    const Grammar& grammar = onlyGrammar(result);
    ASSERT_EQ(grammar.rules.size(), 4u);
    EXPECT_EQ(grammar.rules[0].name, "r");
    EXPECT_EQ(grammar.rules[1].name, "r@rot90y");
    EXPECT_EQ(grammar.rules[2].name, "r@rot180y");
    EXPECT_EQ(grammar.rules[3].name, "r@rot270y");
    EXPECT_EQ(grammar.rules[1].size, glm::ivec3(2, 2, 3));
    EXPECT_EQ(grammar.rules[2].size, glm::ivec3(3, 2, 2));
    EXPECT_EQ(grammar.rules[3].size, glm::ivec3(2, 2, 3));
    for (const Rule& variant : grammar.rules) EXPECT_EQ(variant.loc.line, grammar.rules[0].loc.line);
}

// rot90y maps +x to -z (x' = z, z' = -x): the original's cell (x, y, z) lands at (z, y, 2 - x).
TEST(check_Symmetry, CellsMoveAsTheElementSays) {
    const CheckResult result = check(asymmetricRule("rot_y"));
    const Grammar& grammar = onlyGrammar(result);
    const Rule& original = grammar.rules[0];
    const Rule& turned = grammar.rules[1];
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x) {
                const SymbolCell& from = original.symbol[cellIndex(original.size, x, y, z)];
                const SymbolCell& to = turned.symbol[cellIndex(turned.size, z, y, 2 - x)];
                ASSERT_EQ(to.predicates.size(), 1u);
                EXPECT_EQ(to.predicates[0].value, from.predicates[0].value) << x << "," << y << "," << z;
            }
    // The transform moves with its cells: SET 1 sat at (0, 0, 0).
    EXPECT_EQ(turned.transform[cellIndex(turned.size, 0, 0, 2)].op, TransformOp::SET);
    // mirror_y flips rows: top becomes bottom.
    const CheckResult flippedResult =
        check(oneRule("[1, 2, 1]", "[ABS] [PRES]", "[SET 1] [NOP]", "symmetry = [mirror_y];"));
    const Grammar& flipped = onlyGrammar(flippedResult);
    ASSERT_EQ(flipped.rules.size(), 2u);
    EXPECT_EQ(flipped.rules[1].name, "r@mirror_y");
    EXPECT_EQ(flipped.rules[1].symbol[0].predicates[0].op, SymbolOp::ABS);
    EXPECT_EQ(flipped.rules[1].transform[0].op, TransformOp::SET);
}

TEST(check_Symmetry, ListFormAndGrammarDefault) {
    const CheckResult listedResult = check(asymmetricRule("[mirror_x, rot90y_mirror_y]"));
    const Grammar& listed = onlyGrammar(listedResult);
    ASSERT_EQ(listed.rules.size(), 3u);
    EXPECT_EQ(listed.rules[1].name, "r@mirror_x");
    EXPECT_EQ(listed.rules[2].name, "r@rot90y_mirror_y");
    // The grammar's key applies to rules without their own; a rule's key overrides it.
    const std::string text =
        "world { size = [16, 16, 16]; }\ngrammar g {\n  symmetry = xz;\n"
        "  rule a { size = [2, 1, 1]; symbol { [PRES, ABS] } transform { [NOP, SET 1] } }\n"
        "  rule b { size = [2, 1, 1]; symmetry = none; symbol { [PRES, ABS] } transform { [NOP, ADD 1] } }\n}\n";
    const CheckResult result = check(text);
    const Grammar& grammar = onlyGrammar(result);
    ASSERT_EQ(grammar.rules.size(), 3u); // a, a@mirror_x (mirror_z and rot180y repeat them), b
    EXPECT_EQ(grammar.rules[1].name, "a@mirror_x");
    EXPECT_EQ(grammar.rules[2].name, "b");
}

TEST(check_Symmetry, ElementsOutsideTheSquareGroupAreNamedByTheirAxes) {
    const CheckResult result = check(asymmetricRule("all"));
    const Grammar& grammar = onlyGrammar(result);
    bool sawPermutation = false;
    for (const Rule& rule : grammar.rules) sawPermutation = sawPermutation || rule.name == "r@[y,x,z]";
    EXPECT_TRUE(sawPermutation);
}

TEST(check_Symmetry, BadValuesAreLocatedErrors) {
    CheckResult unknown = check(asymmetricRule("sqaure"));
    ASSERT_EQ(codes(unknown), Codes{"E0002"});
    EXPECT_NE(unknown.diagnostics[0].message.find("did you mean 'square'"), std::string::npos)
        << unknown.rendered();
    EXPECT_EQ(codes(check(asymmetricRule("[rot90y, rot45y]"))), Codes{"E0002"});
    EXPECT_EQ(codes(check(asymmetricRule("4"))), Codes{"E0010"});
}

TEST(check_Symmetry, WarningsOncePerDeclaredRule) {
    // A cell that can never match: W0202 once, not once per variant.
    EXPECT_EQ(codes(check(oneRule("[2, 1, 1]", "[ABS & GT 0, IGN]", "[NOP, NOP]", "symmetry = square;"))),
              Codes{"W0202"});
    // Variants of one rule overlapping is the point of symmetry: no W0203 among them.
    EXPECT_EQ(codes(check(oneRule("[2, 1, 1]", "[PRES, IGN]", "[NOP, SET 1]", "symmetry = x;"))), Codes{});
    // A variant whose turned window leaves the bounds is named in W0204.
    CheckResult tooDeep = check(oneRule("[3, 1, 1]", "[PRES, PRES, ABS]", "[NOP, NOP, SET 1]", "symmetry = rot_y;",
                                        "bounds = [[0, 0, 0], [16, 16, 2]];"));
    ASSERT_EQ(codes(tooDeep), (Codes{"W0204", "W0204"}));
    EXPECT_NE(tooDeep.diagnostics[0].message.find("'r@rot90y'"), std::string::npos) << tooDeep.rendered();
}

} // namespace symmetry_test
} // namespace voxc
