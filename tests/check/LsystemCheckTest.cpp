// lsystem blocks: the checker maps them onto lsystem::Definition exactly, the printed grammars of
// Mark & Berechet give the spec's strings through the examples, rule files are imported with
// their errors located in the rule file, and formatLsystemBlock writes a block that checks back
// to the same definition.
#include "CheckTestUtil.h"

#include "voxc/generators/lsystem/Evolve.h"
#include "voxc/generators/lsystem/Expand.h"
#include "voxc/generators/lsystem/RuleFile.h"
#include "voxc/generators/lsystem/Turtle.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

#include <filesystem>
#include <fstream>
#include <set>
#include <tuple>

namespace voxc {
namespace lsystem_check_test {

using namespace lsystem;
using test::check;
using test::codes;
using Codes = std::vector<std::string>;

const std::string kWorld = "world { size = [16, 16, 16]; }\n";

const CheckedLsystem& only(const CheckResult& result) {
    EXPECT_TRUE(result.diagnostics.empty()) << result.rendered();
    EXPECT_EQ(result.lsystems.size(), 1u);
    return result.lsystems.at(0);
}

CheckResult example(const std::string& name) {
    return checkFile(std::string(VOXC_EXAMPLES_DIR) + "/" + name + ".vox");
}

// Alternatives compare without their source locations.
bool sameAlternatives(const std::map<char, std::vector<Alternative>>& a, const std::map<char, std::vector<Alternative>>& b) {
    if (a.size() != b.size()) return false;
    for (const auto& [symbol, list] : a) {
        auto it = b.find(symbol);
        if (it == b.end() || it->second.size() != list.size()) return false;
        for (size_t i = 0; i < list.size(); ++i)
            if (std::tie(list[i].text, list[i].type, list[i].weight) !=
                std::tie(it->second[i].text, it->second[i].type, it->second[i].weight))
                return false;
    }
    return true;
}

void expectSameDefinition(const Definition& a, const Definition& b) {
    EXPECT_EQ(a.turtle, b.turtle);
    EXPECT_EQ(a.selection, b.selection);
    EXPECT_EQ(a.axiom, b.axiom);
    EXPECT_EQ(a.expansions, b.expansions);
    EXPECT_EQ(a.seed, b.seed);
    EXPECT_TRUE(sameAlternatives(a.productions, b.productions));
    EXPECT_TRUE(sameAlternatives(a.macros, b.macros));
    const TurtleParams &p = a.params, &q = b.params;
    EXPECT_EQ(std::tie(p.angle, p.step, p.angleDelta, p.stepDelta, p.angleDeviation, p.pitchLimit, p.yaw, p.pitch),
              std::tie(q.angle, q.step, q.angleDelta, q.stepDelta, q.angleDeviation, q.pitchLimit, q.yaw, q.pitch));
    EXPECT_EQ(p.start, q.start);
    ASSERT_EQ(a.target.has_value(), b.target.has_value());
    if (a.target) {
        EXPECT_EQ(std::tie(a.target->point, a.target->strength), std::tie(b.target->point, b.target->strength));
    }
    ASSERT_EQ(a.balanced.has_value(), b.balanced.has_value());
    if (a.balanced) { EXPECT_EQ(a.balanced->delta, b.balanced->delta); }
    ASSERT_EQ(a.constrained.has_value(), b.constrained.has_value());
    if (a.constrained) {
        EXPECT_EQ(std::tie(a.constrained->shape, a.constrained->min, a.constrained->max, a.constrained->center,
                           a.constrained->radius),
                  std::tie(b.constrained->shape, b.constrained->min, b.constrained->max, b.constrained->center,
                           b.constrained->radius));
    }
}

const std::string kFullBlock = "const W = 0.25;\n" + kWorld +
                               "lsystem net {\n"
                               "  turtle = thesis; selection = thesis; axiom = \"ZC\"; expansions = 3; seed = 7;\n"
                               "  angle = 30; step = 2; angle_delta = 4; step_delta = 0.5; angle_deviation = 10;\n"
                               "  pitch_limit = 60; start = [1, 2, 3]; yaw = 90; pitch = -10;\n"
                               "  production Z { \"C[Q]Z\" none 1; \"F0Z\" tunnel -W; }\n"
                               "  macro C { \"FLFLFZ\" tunnel 1; \"FRFRFZ\" tunnel 2; }\n"
                               "  macro Q { \"BF[RFF]SZ\" room; }\n"
                               "  target { point = [100, 0, 5]; strength = 2; }\n"
                               "  balanced { delta = 0.5; }\n"
                               "  constrain { center = [0, 0, 0]; radius = 50; }\n"
                               "  connect { chance = 1; max_distance = 20; frequency = 0.5; amplitude = 2; spacing = 3; }\n"
                               "}\n";

TEST(check_Lsystem, BlockMapsOntoTheDefinitionExactly) {
    CheckResult result = check(kFullBlock);
    const CheckedLsystem& lsystem = only(result);
    EXPECT_EQ(lsystem.name, "net");
    EXPECT_EQ(lsystem.loc.line, 3u);
    Definition expected;
    expected.turtle = TurtleKind::Thesis;
    expected.selection = Selection::Thesis;
    expected.axiom = "ZC";
    expected.expansions = 3;
    expected.seed = 7;
    expected.params = {30, 2, 4, 0.5, 10, 60, {1, 2, 3}, 90, -10};
    expected.productions['Z'] = {{"C[Q]Z", SymbolType::None, 1}, {"F0Z", SymbolType::Tunnel, -0.25}};
    expected.macros['C'] = {{"FLFLFZ", SymbolType::Tunnel, 1}, {"FRFRFZ", SymbolType::Tunnel, 2}};
    expected.macros['Q'] = {{"BF[RFF]SZ", SymbolType::Room, 1}};
    expected.target = TargetMode{{100, 0, 5}, 2};
    expected.balanced = BalancedMode{0.5};
    ConstrainedMode sphere;
    sphere.shape = ConstrainedMode::Shape::Sphere;
    sphere.radius = 50;
    expected.constrained = sphere;
    expectSameDefinition(lsystem.definition, expected);
    EXPECT_EQ(std::tie(lsystem.connect.chance, lsystem.connect.maxDistance, lsystem.connect.frequency,
                       lsystem.connect.amplitude, lsystem.connect.spacing),
              std::make_tuple(1.0, 20.0, 0.5, 2.0, 3.0));
    // The location of each string's first character, for the core's located checks.
    EXPECT_EQ(lsystem.definition.productions.at('Z')[1].loc.line, 7u);
    EXPECT_EQ(lsystem.definition.productions.at('Z')[1].loc.column, 35u);
}

TEST(check_Lsystem, FormattedBlockChecksBackToTheSameDefinition) {
    const CheckResult first = check(kFullBlock);
    const CheckedLsystem& original = only(first);
    const std::string text = formatLsystemBlock("copy", original.definition, original.connect);
    CheckResult again = check(kWorld + text);
    const CheckedLsystem& copy = only(again);
    expectSameDefinition(copy.definition, original.definition);
    EXPECT_EQ(copy.connect.spacing, original.connect.spacing);
}

TEST(check_Lsystem, PrintedGrammarsThroughTheExamples) {
    // Grammar (2): (RF)^8 Z closes an octagon at the start.
    Definition line = only(example("lsystem_line")).definition;
    Expansion e2 = expand(line);
    EXPECT_EQ(e2.symbols, "RFRFRFRFRFRFRFRFZ");
    EXPECT_NEAR(glm::length(interpret(line, e2.symbols).finalPosition), 0.0, 1e-9);
    // Grammar (3): lengths 1 + 17(4^n - 1)/3, 597 leaf endpoints and the trunk at (62, 0, 0) after five.
    Definition branches = only(example("lsystem_branches")).definition;
    Expansion e3 = expand(branches);
    EXPECT_EQ(e3.lengths, (std::vector<uint64_t>{1, 18, 86, 358, 1446, 5798}));
    Skeleton s3 = interpret(branches, e3.symbols);
    EXPECT_EQ(s3.endpoints.size(), 597u);
    EXPECT_NEAR(s3.finalPosition.x, 62.0, 1e-9);
    // Grammar (4): one expansion of Z -> C[H] with single substitutes.
    Definition macros = only(example("lsystem_macros")).definition;
    Expansion e4 = expand(macros);
    EXPECT_EQ(e4.symbols, "FLFLF[FUFFDF]");
    Skeleton s4 = interpret(macros, e4.symbols);
    ASSERT_EQ(s4.endpoints.size(), 1u);
    EXPECT_NEAR(s4.endpoints[0].position.y, 1.414214, 1e-6);
    EXPECT_NEAR(s4.endpoints[0].position.z, -5.121320, 1e-6);
    // The ABOP Hilbert curve visits each of the 4x4x4 lattice points once.
    Definition hilbert = only(example("lsystem_abop_hilbert")).definition;
    Skeleton sh = interpret(hilbert, expand(hilbert).symbols);
    std::set<std::tuple<long, long, long>> points;
    for (const Segment& s : sh.segments)
        for (glm::dvec3 p : {s.from, s.to}) points.emplace(std::lround(p.x), std::lround(p.y), std::lround(p.z));
    EXPECT_EQ(sh.segments.size(), 63u);
    EXPECT_EQ(points.size(), 64u);
}

TEST(check_Lsystem, RuleFileIsImportedAndItsErrorsLocatedInIt) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "voxc_lsystem_rules_test";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "caves.rules") << defaultRuleFileText();
    std::ofstream(dir / "bad.rules") << "I;FFZ;tunnel;1\nC;FXZ;tunnel;1\n";
    std::ofstream(dir / "net.vox") << kWorld << "lsystem net {\n  rules = \"caves.rules\";\n  expansions = 3;\n}\n";
    std::ofstream(dir / "bad.vox") << kWorld << "lsystem net {\n  rules = \"bad.rules\";\n}\n";

    CheckResult result = checkFile((dir / "net.vox").string());
    const CheckedLsystem& net = only(result);
    Diagnostics parsed;
    std::optional<RuleSet> rules = parseRuleFile(SourceFile("caves.rules", std::string(defaultRuleFileText())), parsed);
    ASSERT_TRUE(rules);
    EXPECT_TRUE(sameAlternatives(net.definition.productions, rules->productions));
    EXPECT_TRUE(sameAlternatives(net.definition.macros, rules->macros));
    EXPECT_EQ(net.rulesPath, (dir / "caves.rules").string());

    CheckResult bad = checkFile((dir / "bad.vox").string());
    ASSERT_EQ(codes(bad), Codes{"E0002"});
    const Diagnostic& d = bad.diagnostics[0];
    ASSERT_TRUE(d.file);
    EXPECT_EQ(d.file->path(), (dir / "bad.rules").string());
    EXPECT_EQ(std::tie(d.loc.line, d.loc.column), std::make_tuple(2u, 4u));
    EXPECT_NE(bad.rendered().find("bad.rules:2:4: error E0002"), std::string::npos) << bad.rendered();
    std::filesystem::remove_all(dir);
}

TEST(check_Lsystem, ErrorsAreLocatedAtTheirCharacter) {
    CheckResult result = check(kWorld + "lsystem net {\n  production Z { \"FZ[RQZ]\"; }\n}\n");
    ASSERT_EQ(codes(result), Codes{"E0002"});
    EXPECT_EQ(std::tie(result.diagnostics[0].loc.line, result.diagnostics[0].loc.column), std::make_tuple(3u, 23u));
}

TEST(check_Lsystem, PredictedLimitsAreE0012AtTheBlock) {
    CheckResult result = check(kWorld + "lsystem grow {\n  expansions = 16;\n  production Z { \"ZZZZ\"; }\n}\n");
    ASSERT_EQ(codes(result), Codes{"E0012"});
    EXPECT_EQ(result.diagnostics[0].loc.line, 2u);
    EXPECT_EQ(codes(check(kWorld + "lsystem grow {\n  expansions = 40;\n  production Z { \"ZZ\"; }\n}\n")),
              Codes{"E0012"});
}

TEST(check_Lsystem, StringsWhereTheyDoNotBelong) {
    EXPECT_EQ(codes(check("world { size = \"big\"; }")), Codes{"E0010"});
    EXPECT_EQ(codes(check("world { size = [16, 16, 16]; seed = \"1\"; }")), Codes{"E0010"});
    EXPECT_EQ(codes(check("world { size = [16, 16, 16]; \"FZ\"; }")), Codes{"E0008"});
    EXPECT_EQ(codes(check(kWorld + "lsystem a { }\nlsystem a { }\n")), Codes{"E0003"});
    EXPECT_EQ(codes(check(kWorld + "lsystem a { }\npipeline { start; union a; }\n")), Codes{"E0013"});
}

// random_rules draws `count` alternatives of the production from the block's seed (§III-B.1):
// each has the drawn number of macros from the weighted ones, never an excluded one, at least
// one bracket pair; the same seed draws the same rules and another seed others.
TEST(check_Lsystem, RandomRulesDrawProductionsFromTheSeed) {
    const auto drawn = [](uint32_t seed) {
        const CheckResult result = check(kWorld + fmt::format(R"(lsystem net {{
  seed = {};
  production Z {{ "I"; }}
  macro I {{ "FFZ" tunnel 1; }}
  macro C {{ "FLFZ" tunnel 1; }}
  macro T {{ "FUFDZ" tunnel 1; }}
  random_rules {{ count = 3; macros = [4, 5]; bracket_chance = 0.5; weights {{ C = 0.5; T = -1; }} }}
}}
)", seed));
        return only(result).definition.productions.at('Z');
    };
    const std::vector<Alternative> first = drawn(5);
    ASSERT_EQ(first.size(), 4u);
    EXPECT_EQ(first[0].text, "I"); // the written alternative stays first
    for (size_t k = 1; k < first.size(); ++k) {
        const std::string& text = first[k].text;
        const size_t macros = size_t(std::count_if(text.begin(), text.end(), [](char c) { return c != '[' && c != ']'; }));
        EXPECT_TRUE(macros == 4 || macros == 5) << text;
        EXPECT_EQ(text.find('T'), std::string::npos) << text;
        EXPECT_FALSE(bracketPairs(text).empty()) << text;
        EXPECT_NE(text.front(), '[') << text;
    }
    const std::vector<Alternative> again = drawn(5), other = drawn(6);
    for (size_t k = 1; k < first.size(); ++k) EXPECT_EQ(first[k].text, again[k].text);
    bool differs = false;
    for (size_t k = 1; k < first.size(); ++k) differs = differs || first[k].text != other[k].text;
    EXPECT_TRUE(differs);
}

} // namespace lsystem_check_test
} // namespace voxc
