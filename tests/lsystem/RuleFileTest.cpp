// The paper's rule file format (lsystem-spec.md §2.3): records, codes and locations, the
// shipped reconstruction, and golden renderings of every error (rule_cases/NAME.rules against
// NAME.expected; VOXC_UPDATE_GOLDENS=1 rewrites them: scripts/update-lsystem-goldens.sh).
#include "TestDefinitions.h"
#include "voxc/core/AtomicWrite.h"
#include "voxc/generators/lsystem/Expand.h"
#include "voxc/generators/lsystem/RuleFile.h"
#include "voxc/generators/lsystem/Selection.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

namespace voxc::lsystem {
namespace {

namespace fs = std::filesystem;

std::optional<RuleSet> parse(const std::string& text, Diagnostics& diagnostics) {
    return parseRuleFile(SourceFile("test.rules", text), diagnostics);
}

TEST(lsystem_RuleFile, RecordsBecomeProductionsAndMacros) {
    Diagnostics diagnostics;
    const auto rules = parse("# comment\n\n  C ; FLFLFZ ; tunnel ; 0.5  \r\nC;FRFRFZ;tunnel;-1\nZ;C[C];none;1\n", diagnostics);
    ASSERT_TRUE(rules) << diagnostics.all().front().message;
    ASSERT_EQ(rules->macros.at('C').size(), 2u);
    const Alternative& first = rules->macros.at('C')[0];
    EXPECT_EQ(first.text, "FLFLFZ");
    EXPECT_EQ(first.type, SymbolType::Tunnel);
    EXPECT_EQ(first.weight, 0.5);
    EXPECT_EQ(first.loc.line, 3u);
    EXPECT_EQ(first.loc.column, 7u);
    EXPECT_EQ(rules->macros.at('C')[1].weight, -1.0);
    ASSERT_EQ(rules->productions.at('Z').size(), 1u);
    EXPECT_EQ(rules->productions.at('Z')[0].text, "C[C]");
    EXPECT_TRUE(diagnostics.all().empty());
}

TEST(lsystem_RuleFile, ErrorsCarryCodesAndColumns) {
    struct Case {
        const char* text;
        const char* code;
        uint32_t line, column;
    } cases[] = {{"C;FZ;tunnel\n", "E0001", 1, 1},         {"C;F[Z;tunnel;1\n", "E0001", 1, 4},
                 {"Z;F]F;none;1\n", "E0001", 1, 4},         {"C;FXZ;tunnel;1\n", "E0002", 1, 4},
                 {"C;FZ;tunel;1\n", "E0002", 1, 6},         {"F;FZ;tunnel;1\n", "E0003", 1, 1},
                 {"C; ;tunnel;1\n", "E0009", 1, 4},         {"C;FZ;tunnel;abc\n", "E0010", 1, 13},
                 {"C;FZ;tunnel;1e999\n", "E0007", 1, 13},   {"C;FZ;tunnel;1\nT;FC;tunnel;1\n", "E0013", 2, 4},
                 {"\nZ;Q[Q];none;1\n", "E0002", 2, 3}};
    for (const Case& c : cases) {
        Diagnostics diagnostics;
        EXPECT_FALSE(parse(c.text, diagnostics)) << c.text;
        ASSERT_EQ(diagnostics.all().size(), 1u) << c.text;
        const Diagnostic& d = diagnostics.all().front();
        EXPECT_EQ(d.code, c.code) << c.text << ": " << d.message;
        EXPECT_EQ(d.loc.line, c.line) << c.text;
        EXPECT_EQ(d.loc.column, c.column) << c.text;
    }
}

TEST(lsystem_RuleFile, TooManyAlternativesIsALimit) {
    std::string text;
    for (int i = 0; i < 5; ++i) text += "C;FZ;tunnel;1\n";
    Limits limits;
    limits.maxAlternatives = 4;
    Diagnostics diagnostics;
    EXPECT_FALSE(parseRuleFile(SourceFile("many.rules", text), diagnostics, limits));
    ASSERT_EQ(diagnostics.all().size(), 1u);
    EXPECT_EQ(diagnostics.all().front().code, "E0012");
    EXPECT_EQ(diagnostics.all().front().loc.line, 5u);
}

Definition fromDefaultRules(uint32_t seed) {
    Diagnostics diagnostics;
    const auto rules = parseRuleFile(SourceFile("default.rules", std::string(defaultRuleFileText())), diagnostics);
    EXPECT_TRUE(rules);
    Definition d;
    d.productions = rules->productions;
    d.macros = rules->macros;
    d.expansions = 3;
    d.seed = seed;
    return d;
}

TEST(lsystem_RuleFile, TheShippedReconstructionParsesAndIsStochastic) {
    const Definition d = fromDefaultRules(7);
    EXPECT_TRUE(checkDefinition(d).empty());
    EXPECT_EQ(d.macros.size(), 5u);
    EXPECT_EQ(d.macros.at('Q')[0].type, SymbolType::Room);
    const Expansion a = expand(d), b = expand(d), c = expand(fromDefaultRules(8));
    EXPECT_EQ(a.symbols, b.symbols);
    EXPECT_NE(a.symbols, c.symbols);
}

// Arbitrary bytes never crash the parser: it returns rules or reports at least one error.
TEST(lsystem_RuleFile, ArbitraryBytesParseOrReport) {
    std::string alphabet = "ZCQIFRL[];;;#\n\r \t.-1e9noetunlrom";
    alphabet += '\0';
    alphabet += '\xff';
    for (uint32_t seed = 0; seed < 1000; ++seed) {
        std::string text;
        for (uint32_t i = 0; i < 80; ++i) text += alphabet[uniformIndex({seed, Stream::Mutation, 7, i, 0}, uint32_t(alphabet.size()))];
        Diagnostics diagnostics;
        const auto rules = parse(text, diagnostics);
        EXPECT_EQ(rules.has_value(), !diagnostics.hasErrors()) << text;
    }
}

const fs::path kCases = VOXC_LSYSTEM_RULE_CASES_DIR;

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<std::string> caseNames() {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(kCases))
        if (entry.path().extension() == ".rules") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

class lsystem_RuleFileGolden : public testing::TestWithParam<std::string> {};

TEST_P(lsystem_RuleFileGolden, MatchesExpected) {
    const std::string name = GetParam();
    const SourceFile source(name + ".rules", readFile(kCases / (name + ".rules")));
    Diagnostics diagnostics;
    EXPECT_FALSE(parseRuleFile(source, diagnostics));
    const std::string rendered = renderAll(diagnostics.take(), source);
    const fs::path expected = kCases / (name + ".expected");
    const char* update = std::getenv("VOXC_UPDATE_GOLDENS");
    if (update && std::string(update) == "1") {
        writeFileAtomically(expected.string(), rendered);
        GTEST_SKIP() << "updated " << expected;
    }
    ASSERT_TRUE(fs::exists(expected)) << "no golden file; run scripts/update-lsystem-goldens.sh";
    EXPECT_EQ(rendered, readFile(expected));
}

INSTANTIATE_TEST_SUITE_P(cases, lsystem_RuleFileGolden, testing::ValuesIn(caseNames()),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

} // namespace
} // namespace voxc::lsystem
