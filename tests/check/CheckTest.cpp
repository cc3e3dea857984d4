// The checker's Program and its error codes. Rendered wording is covered by the golden
// cases in tests/diagnostics; these tests pin codes, locations and values.
#include "CheckTestUtil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace voxc {
namespace check_test {

using test::check;
using test::codes;
using test::oneRule;
using Codes = std::vector<std::string>;

const char* kMinimal = "world { size = [16, 8, 4]; }";

TEST(check_World, DefaultsAndValues) {
    CheckResult result = check("world { size = [16, 8, 4]; origin = [-100, 5, 1000000]; chunk = 8; seed = 4294967295; }");
    ASSERT_TRUE(result.program) << result.rendered();
    const World& world = result.program->world;
    EXPECT_EQ(world.size, glm::ivec3(16, 8, 4));
    EXPECT_EQ(world.origin, glm::ivec3(-100, 5, 1000000));
    EXPECT_EQ(world.chunkSize, 8);
    EXPECT_EQ(world.seed, 4294967295u);

    CheckResult defaults = check(kMinimal);
    ASSERT_TRUE(defaults.program);
    EXPECT_EQ(defaults.program->world.chunkSize, 32);
    EXPECT_EQ(defaults.program->world.seed, 0u);
    EXPECT_EQ(defaults.program->pipeline.size(), 1u);
    EXPECT_EQ(defaults.program->sourcePath, "test.vox");
}

TEST(check_World, SeedOutsideTheUint32RangeNamesBothBounds) {
    for (const char* seed : {"4294967296", "99999999999999999999", "-1"}) {
        CheckResult result = check(std::string("world { size = [8, 8, 8]; seed = ") + seed + "; }");
        ASSERT_EQ(codes(result), Codes{"E0007"}) << seed;
        EXPECT_NE(result.diagnostics[0].message.find("between 0 and 4294967295"), std::string::npos)
            << result.diagnostics[0].message;
    }
}

TEST(check_World, ChunkMustBeAPowerOfTwoFrom8To64) {
    for (int chunk : {8, 16, 32, 64})
        EXPECT_FALSE(check("world { size = [8, 8, 8]; chunk = " + std::to_string(chunk) + "; }").hasErrors());
    for (int chunk : {4, 12, 128})
        EXPECT_EQ(codes(check("world { size = [8, 8, 8]; chunk = " + std::to_string(chunk) + "; }")), Codes{"E0007"});
}

TEST(check_Constants, FoldInDeclarationOrder) {
    CheckResult result = check("const A = 2; const B = -(A + 1) * 4 / 8; const C = B - -1.5;\n"
                               "world { size = [A * 8, A, 4]; }\n" +
                               test::withoutWorld(oneRule("[1, 1, 1]", "[GEQ C]", "[ADD B]")));
    ASSERT_TRUE(result.program) << result.rendered();
    EXPECT_EQ(result.program->world.size, glm::ivec3(16, 2, 4));
    const Rule& rule = result.program->grammars[0].rules[0];
    EXPECT_EQ(rule.symbol[0].predicates[0].value, 0.0f); // -1.5 + 1.5
    EXPECT_EQ(rule.transform[0].value, -1.5f);
}

TEST(check_Constants, Errors) {
    CheckResult unknown = check("const A = B; const B = 1; world { size = [8, 8, 8]; }");
    EXPECT_EQ(codes(unknown), Codes{"E0002"}); // B is not declared yet where A uses it
    EXPECT_EQ(unknown.diagnostics[0].loc.column, 11u);

    CheckResult divide = check("const Z = 0; const Q = 1 / (Z * 2); world { size = [8, 8, 8]; }");
    EXPECT_EQ(codes(divide), Codes{"E0007"});
    EXPECT_NE(divide.diagnostics[0].message.find("division by zero"), std::string::npos);

    // A failed constant is reported once, not again where it is used.
    EXPECT_EQ(codes(check("const Q = 1 / 0; world { size = [Q, 8, 8]; }")), Codes{"E0007"});
    EXPECT_EQ(codes(check("const A = 1; const A = 2; world { size = [8, 8, 8]; }")), Codes{"E0003"});
}

TEST(check_Rule, WeightAndProbabilityUnits) {
    CheckResult result = check(oneRule("[1, 1, 1]", "[PRES]", "[NOP]", "weight = 2.5; probability = 0.3; priority = -4;"));
    ASSERT_TRUE(result.program) << result.rendered();
    const Rule& rule = result.program->grammars[0].rules[0];
    EXPECT_EQ(rule.name, "r");
    EXPECT_EQ(rule.weight, 2.5f);
    EXPECT_EQ(rule.weightUnits, 2500u);
    EXPECT_EQ(rule.probability, 0.3f);
    EXPECT_EQ(rule.probabilityUnits, uint32_t(std::llround(0.3 * (1 << 24))));
    EXPECT_EQ(rule.priority, -4);

    CheckResult defaults = check(oneRule("[1, 1, 1]", "[PRES]", "[NOP]"));
    ASSERT_TRUE(defaults.program);
    EXPECT_EQ(defaults.program->grammars[0].rules[0].weightUnits, 1000u);
    EXPECT_EQ(defaults.program->grammars[0].rules[0].probabilityUnits, kProbabilityOne);

    EXPECT_EQ(codes(check(oneRule("[1, 1, 1]", "[PRES]", "[NOP]", "weight = 1000.5;"))), Codes{"E0007"});
    EXPECT_EQ(codes(check(oneRule("[1, 1, 1]", "[PRES]", "[NOP]", "weight = 0.0004;"))), Codes{"E0007"});
    EXPECT_EQ(codes(check(oneRule("[1, 1, 1]", "[PRES]", "[NOP]", "probability = -0.1;"))), Codes{"E0007"});
    EXPECT_EQ(codes(check(oneRule("[1, 1, 1]", "[PRES]", "[NOP]", "priority = 0.5;"))), Codes{"E0010"});
}

TEST(check_Grammar, DefaultsBoundsAndClamp) {
    CheckResult defaults = check(oneRule("[1, 1, 1]", "[PRES]", "[NOP]"));
    ASSERT_TRUE(defaults.program);
    const Grammar& plain = defaults.program->grammars[0];
    EXPECT_EQ(plain.stride, glm::ivec3(1));
    EXPECT_EQ(plain.boundsMin, glm::ivec3(0));
    EXPECT_EQ(plain.boundsMax, glm::ivec3(16));
    EXPECT_EQ(plain.iterations, 1);
    EXPECT_FALSE(plain.clampMin.has_value());

    CheckResult set = check(oneRule("[1, 1, 1]", "[PRES]", "[NOP]", "",
                                    "stride = [2, 1, 3]; bounds = [[1, 2, 3], [16, 10, 9]]; iterations = 7; "
                                    "clamp = [-1, 0.5];"));
    ASSERT_TRUE(set.program) << set.rendered();
    const Grammar& grammar = set.program->grammars[0];
    EXPECT_EQ(grammar.stride, glm::ivec3(2, 1, 3));
    EXPECT_EQ(grammar.boundsMin, glm::ivec3(1, 2, 3));
    EXPECT_EQ(grammar.boundsMax, glm::ivec3(16, 10, 9));
    EXPECT_EQ(grammar.iterations, 7);
    EXPECT_EQ(grammar.clampMin, -1.0f);
    EXPECT_EQ(grammar.clampMax, 0.5f);

    // Nothing is clipped silently: bounds reaching outside the grid are an error.
    EXPECT_EQ(codes(check(oneRule("[1, 1, 1]", "[PRES]", "[NOP]", "", "bounds = [[0, 0, 0], [17, 16, 16]];"))),
              Codes{"E0007"});
    EXPECT_EQ(codes(check(oneRule("[1, 1, 1]", "[PRES]", "[NOP]", "", "stride = [0, 1, 1];"))), Codes{"E0007"});
}

TEST(check_Start, ShapesComeFromTheRegistry) {
    CheckResult result = check("world { size = [32, 32, 32]; }\n"
                               "start { fill { value = 0.25; } box { min = [0, 0, 0]; max = [8, 9, 10]; }\n"
                               "  wall { axis = z; at = 3; thickness = 2; value = 0.5; }\n"
                               "  heightfield { base = 10; octaves = 2; } }");
    ASSERT_TRUE(result.program) << result.rendered();
    const auto& start = result.program->start;
    ASSERT_EQ(start.size(), 4u);
    EXPECT_EQ(start[0].kind, ShapeKind::Fill);
    EXPECT_EQ(start[0].value, 0.25f);
    EXPECT_EQ(start[1].kind, ShapeKind::Box);
    EXPECT_EQ(start[1].max, glm::vec3(8, 9, 10));
    EXPECT_EQ(start[1].value, 1.0f);
    EXPECT_EQ(start[2].axis, 2);
    EXPECT_EQ(start[2].thickness, 2.0f);
    EXPECT_EQ(start[3].heightfield.base, 10.0f);
    EXPECT_EQ(start[3].heightfield.octaves, 2);

    EXPECT_EQ(codes(check("world { size = [8, 8, 8]; } start { sphere { center = [1, 1, 1]; } }")), Codes{"E0009"});
    EXPECT_EQ(codes(check("world { size = [8, 8, 8]; } start { heightfield { octaves = 1.5; } }")), Codes{"E0010"});
    EXPECT_EQ(codes(check("world { size = [8, 8, 8]; } start { cube { } }")), Codes{"E0002"});
}

TEST(check_Pipeline, ExplicitAndDefaultOrder) {
    const std::string grammars = "world { size = [8, 8, 8]; }\n"
                                 "grammar a { rule r { size = [1, 1, 1]; symbol { [PRES] } transform { [NOP] } } }\n"
                                 "grammar b { rule r { size = [1, 1, 1]; symbol { [ABS] } transform { [NOP] } } }\n";
    CheckResult defaults = check(grammars);
    ASSERT_TRUE(defaults.program);
    const auto& order = defaults.program->pipeline;
    ASSERT_EQ(order.size(), 3u);
    EXPECT_EQ(order[0].kind, Stage::Kind::Start);
    EXPECT_EQ(order[1].index, 0u);
    EXPECT_EQ(order[2].index, 1u);

    CheckResult explicitOrder = check(grammars + "pipeline { start; b; a; b; }");
    ASSERT_TRUE(explicitOrder.program) << explicitOrder.rendered();
    const auto& stages = explicitOrder.program->pipeline;
    ASSERT_EQ(stages.size(), 4u);
    EXPECT_EQ(stages[1].index, 1u);
    EXPECT_EQ(stages[2].index, 0u);
    EXPECT_EQ(stages[3].index, 1u);

    EXPECT_EQ(codes(check(grammars + "pipeline { start; c; }")), Codes{"E0002"});
    EXPECT_EQ(codes(check(grammars + "pipeline { a; }")), Codes{"E0009"});
}

// One small file per error code, asserting the code alone (wording is in the goldens).
TEST(check_Errors, EveryCode) {
    const std::string world = "world { size = [8, 8, 8]; }\n";
    EXPECT_EQ(codes(check("world { size = [8, 8, 8] }")), Codes{"E0001"});
    EXPECT_EQ(codes(check(world + "pipeline { start; nothing; }")), Codes{"E0002"});
    EXPECT_EQ(codes(check("world { size = [8, 8, 8]; seed = 1; seed = 2; }")), Codes{"E0003"});
    EXPECT_EQ(codes(check(oneRule("[1, 2, 1]", "[PRES]", "[NOP] [NOP]"))), Codes{"E0004"});
    EXPECT_EQ(codes(check(oneRule("[2, 2, 1]", "[PRES] [PRES, ABS]", "[NOP, NOP] [NOP, NOP]"))), Codes{"E0005"});
    EXPECT_EQ(codes(check(oneRule("[1, 1, 1]", "[IGN 0.5]", "[NOP]"))), Codes{"E0006"});
    EXPECT_EQ(codes(check(oneRule("[1, 1, 1]", "[GEQ]", "[NOP]"))), Codes{"E0006"});
    EXPECT_EQ(codes(check("world { size = [0, 8, 8]; }")), Codes{"E0007"});
    EXPECT_EQ(codes(check("world { size = [8, 8, 8]; colour = 1; }")), Codes{"E0008"});
    EXPECT_EQ(codes(check("world { }")), Codes{"E0009"});
    EXPECT_EQ(codes(check("world { size = [8, 8]; }")), Codes{"E0010"});
    EXPECT_EQ(codes(check(oneRule("[1, 1, 1]", "[MAYBE]", "[NOP]"))), Codes{"E0011"});
    EXPECT_EQ(codes(check("world { size = [1024, 1024, 1024]; }")), Codes{"E0012"});
    EXPECT_EQ(codes(check(world + "lsystem caves { }\npipeline { start; subtract caves; }")), Codes{"E0013"});
    EXPECT_EQ(codes(check("")), Codes{"E0009"});
}

TEST(check_Errors, LimitsAreConfigurable) {
    Limits limits;
    limits.maxVoxels = 100;
    EXPECT_EQ(codes(checkSource(SourceFile("t.vox", "world { size = [8, 8, 8]; }"), limits)), Codes{"E0012"});
    limits = {};
    limits.maxIterations = 3;
    EXPECT_EQ(codes(checkSource(SourceFile("t.vox", oneRule("[1, 1, 1]", "[PRES]", "[NOP]", "", "iterations = 4;")),
                                limits)),
              Codes{"E0012"});
    limits = {};
    limits.maxRulesPerSweep = 1;
    std::string two = "world { size = [8, 8, 8]; }\ngrammar g {\n"
                      "  rule a { size = [1, 1, 1]; symbol { [PRES] } transform { [NOP] } }\n"
                      "  rule b { size = [1, 1, 1]; symbol { [ABS] } transform { [NOP] } } }";
    EXPECT_EQ(codes(checkSource(SourceFile("t.vox", two), limits)), Codes{"E0012"});
}

TEST(check_Errors, SyntaxErrorsRecoverAndStopBeforeChecking) {
    // Three syntax errors in one file; the unknown key is not reported because checking
    // does not run on a tree with syntax errors.
    CheckResult result = check("world { size = [8, 8, 8] colour = 1; }\n"
                               "grammar g { rule r { size = [1, 1, 1]; symbol { [PRES } transform { [NOP] } } }\n"
                               "start { box { min = [0, 0, 0]; max = [1, 1, 1] } }\n");
    EXPECT_EQ(codes(result), (Codes{"E0001", "E0001", "E0001"})) << result.rendered();
    EXPECT_EQ(result.diagnostics[0].loc.line, 1u);
    EXPECT_EQ(result.diagnostics[1].loc.line, 2u);
    EXPECT_EQ(result.diagnostics[2].loc.line, 3u);
    EXPECT_FALSE(result.program);
}

TEST(check_Errors, ManyIndependentErrorsInOneFile) {
    CheckResult result = check("world { size = [8, 8, 8]; chunk = 3; }\n"
                               "start { box { min = [0, 0, 0]; } }\n" +
                               test::withoutWorld(oneRule("[1, 1, 1]", "[GQE 1]", "[ADD]")));
    EXPECT_EQ(codes(result), (Codes{"E0007", "E0009", "E0011", "E0006"})) << result.rendered();
}

TEST(check_Files, MissingAndBinaryFiles) {
    CheckResult missing = checkFile("/nonexistent/dir/file.vox");
    EXPECT_EQ(codes(missing), Codes{"E0100"});
    EXPECT_FALSE(missing.program);

    const std::string path = testing::TempDir() + "voxc_binary_test.vox";
    {
        std::ofstream out(path, std::ios::binary);
        out << std::string("world {\0\x01\x02", 10);
    }
    EXPECT_EQ(codes(checkFile(path)), Codes{"E0101"});
    std::filesystem::remove(path);
    EXPECT_EQ(codes(check("world { size = [8, 8, 8]; } // \xC3\x28")), Codes{"E0101"});
    EXPECT_FALSE(check("world { size = [8, 8, 8]; } // caf\xC3\xA9, \xE2\x82\xAC").hasErrors());
}

} // namespace check_test
} // namespace voxc
