// The two selection rules (lsystem-spec.md §2.4; §10 test 10): argmax(u + w) under `thesis`,
// max(w, 0)-proportional sampling under `weighted`, 10^5 draws each, within 0.01.
#include "TestDefinitions.h"
#include "voxc/generators/lsystem/Expand.h"
#include "voxc/generators/lsystem/Selection.h"

#include <gtest/gtest.h>
#include <vector>

namespace voxc::lsystem {
namespace {

constexpr uint32_t kDraws = 100000;

std::vector<double> frequencies(Selection rule, std::vector<double> weights, uint32_t seed = 5) {
    std::vector<double> counts(weights.size(), 0.0);
    for (uint32_t i = 0; i < kDraws; ++i) counts[choose(rule, weights, {}, {seed, Stream::Macro, 1, i, 0})] += 1;
    for (double& c : counts) c /= kDraws;
    return counts;
}

void expectFrequencies(Selection rule, std::vector<double> weights, std::vector<double> expected) {
    const std::vector<double> actual = frequencies(rule, weights);
    for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(actual[i], expected[i], 0.01) << "candidate " << i;
}

TEST(lsystem_Selection, ThesisRuleIsArgmaxOfUniformPlusWeight) {
    expectFrequencies(Selection::Thesis, {0.5, 0}, {0.875, 0.125});
    expectFrequencies(Selection::Thesis, {0.25, 0}, {0.71875, 0.28125});
    expectFrequencies(Selection::Thesis, {0.5, 0, 0}, {0.79167, 0.10417, 0.10417});
    expectFrequencies(Selection::Thesis, {0, 0}, {0.5, 0.5});
}

TEST(lsystem_Selection, ThesisRuleIsDeterministicForAWeightGapOfOne) {
    EXPECT_EQ(frequencies(Selection::Thesis, {2, 1})[0], 1.0);
    EXPECT_EQ(frequencies(Selection::Thesis, {0, -1})[0], 1.0);
}

TEST(lsystem_Selection, WeightedRuleIsProportional) {
    expectFrequencies(Selection::Weighted, {2, 1}, {2.0 / 3, 1.0 / 3});
    expectFrequencies(Selection::Weighted, {1, 1, 2}, {0.25, 0.25, 0.5});
    EXPECT_EQ(frequencies(Selection::Weighted, {1, -1})[0], 1.0);
}

TEST(lsystem_Selection, WeightedRuleWithoutPositiveWeightTakesTheLargest) {
    EXPECT_EQ(frequencies(Selection::Weighted, {-1, 0, 0})[1], 1.0);
}

TEST(lsystem_Selection, EqualOffsetsChangeNothing) {
    const std::vector<double> weights{1, 2, 3}, shifted{7, 7, 7}, huge{1e6, 1e6, 1e6};
    for (uint32_t i = 0; i < 1000; ++i) {
        const DrawKey key{3, Stream::Macro, 2, i, 1};
        const size_t plain = choose(Selection::Weighted, weights, {}, key);
        EXPECT_EQ(choose(Selection::Weighted, weights, shifted, key), plain);
        EXPECT_EQ(choose(Selection::Weighted, weights, huge, key), plain);
        EXPECT_EQ(choose(Selection::Thesis, weights, shifted, key), choose(Selection::Thesis, weights, {}, key));
    }
}

TEST(lsystem_Selection, DrawsAreUniformAndKeyed) {
    double sum = 0;
    for (uint32_t i = 0; i < kDraws; ++i) {
        const double u = uniform({1, Stream::Jitter, 0, i, 0});
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        sum += u;
    }
    EXPECT_NEAR(sum / kDraws, 0.5, 0.005);
    EXPECT_EQ(uniform({1, Stream::Jitter, 0, 9, 0}), uniform({1, Stream::Jitter, 0, 9, 0}));
    EXPECT_NE(uniform({1, Stream::Jitter, 0, 9, 0}), uniform({2, Stream::Jitter, 0, 9, 0}));
    EXPECT_NE(uniform({1, Stream::Jitter, 0, 9, 0}), uniform({1, Stream::Macro, 0, 9, 0}));
}

// The same statistics through expansion: each macro occurrence of the axiom is one choice.
TEST(lsystem_Selection, MacroSubstitutesFollowTheRuleDuringExpansion) {
    for (Selection rule : {Selection::Thesis, Selection::Weighted}) {
        Definition d = test::thesisDefinition(std::string(kDraws, 'C'));
        d.selection = rule;
        d.macros['C'] = {{"F", SymbolType::Tunnel, 0.5}, {"R", SymbolType::Tunnel, 0}};
        const Expansion e = expand(d, {.recordChoices = true});
        ASSERT_EQ(e.choices.size(), kDraws);
        const double first = double(std::count(e.symbols.begin(), e.symbols.end(), 'F')) / kDraws;
        EXPECT_NEAR(first, rule == Selection::Thesis ? 0.875 : 1.0, 0.01);
    }
}

} // namespace
} // namespace voxc::lsystem
