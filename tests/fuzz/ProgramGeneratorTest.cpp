// The differential fuzzer's generator: a seed names one program, and the programs are valid, so
// the fuzzer compares them instead of counting rejections.
#include "ProgramGenerator.h"
#include "voxc/check/Check.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace voxc::fuzz {
namespace {

TEST(ProgramGenerator, SameSeedSameProgram) {
    EXPECT_EQ(generateProgram(42), generateProgram(42));
    EXPECT_NE(generateProgram(42), generateProgram(43));
}

TEST(ProgramGenerator, EveryProgramChecks) {
    int withGrammar = 0, withField = 0, withMaterial = 0, withVariants = 0, withAggregates = 0, withStamps = 0,
        withLsystemStamps = 0, withDenseCaves = 0, withExtremeBounds = 0;
    for (uint64_t seed = 1; seed <= 300; ++seed) {
        const std::string text = generateProgram(seed);
        const CheckResult result = checkSource(SourceFile(fmt::format("seed{}.vox", seed), text));
        ASSERT_FALSE(result.hasErrors()) << text << result.rendered();
        withGrammar += !result.program->grammars.empty();
        withField += !result.program->fields.empty();
        withMaterial += result.program->usesMaterials();
        bool variant = false, aggregate = false, stamp = false, lsystemStamp = false; // a variant is named rule@element
        for (const Grammar& grammar : result.program->grammars)
            for (const Rule& rule : grammar.rules) {
                variant = variant || rule.name.find('@') != std::string::npos;
                aggregate = aggregate || !rule.aggregates.empty();
                stamp = stamp || !rule.stamps.empty();
                for (const Stamp& s : rule.stamps)
                    for (const FieldNode& node : result.program->fields.at(s.field).nodes)
                        lsystemStamp = lsystemStamp || node.kind == FieldNode::Kind::PointSet;
            }
        withVariants += variant;
        withAggregates += aggregate;
        withStamps += stamp;
        withLsystemStamps += lsystemStamp;
        // A dense lsystem_cave carve (its spacing key) and a `where` bound near the float range's end.
        withDenseCaves += text.find("spacing = ") != std::string::npos;
        withExtremeBounds += text.find("e+3") != std::string::npos;
    }
    // Each part of the language shows up in a fair share of the programs.
    EXPECT_GT(withGrammar, 100);
    EXPECT_GT(withField, 100);
    EXPECT_GT(withMaterial, 100);
    EXPECT_GT(withVariants, 30);
    EXPECT_GT(withAggregates, 30);
    EXPECT_GT(withStamps, 30);
    EXPECT_GT(withLsystemStamps, 5);
    EXPECT_GT(withDenseCaves, 5);
    EXPECT_GT(withExtremeBounds, 5);
}

} // namespace
} // namespace voxc::fuzz
