// Expansion (lsystem-spec.md §2.2, §4.1, §4.2; §10 tests 11 and 18): determinism, several
// productions, the modes, the predicted length and the limits.
#include "TestDefinitions.h"
#include "voxc/generators/lsystem/Expand.h"
#include "voxc/generators/lsystem/Turtle.h"

#include <gtest/gtest.h>

namespace voxc::lsystem {
namespace {

using test::thesisDefinition;
using test::withProduction;

Definition stochastic(uint32_t seed) {
    Definition d = withProduction("I[I][I]", 3);
    d.seed = seed;
    d.macros['I'] = {{"FFFFZ", SymbolType::Tunnel, 1}, {"RFFFFZ", SymbolType::Tunnel, 1}, {"LFFFFZ", SymbolType::Tunnel, 1}};
    return d;
}

TEST(lsystem_Expand, SameSeedSameStringOtherSeedOtherString) {
    const Expansion a = expand(stochastic(7)), b = expand(stochastic(7)), c = expand(stochastic(8));
    EXPECT_EQ(a.symbols, b.symbols);
    EXPECT_EQ(a.types, b.types);
    EXPECT_NE(a.symbols, c.symbols);
}

TEST(lsystem_Expand, SeveralProductionsAreChosenPerOccurrence) {
    Definition d = withProduction("FZ", 6);
    d.productions['Z'].push_back({"RFZ", SymbolType::None, 1});
    d.seed = 3;
    const Expansion e = expand(d, {.recordChoices = true});
    EXPECT_EQ(e.choices.size(), 6u);
    const auto turns = std::count(e.symbols.begin(), e.symbols.end(), 'R');
    EXPECT_GT(turns, 0);
    EXPECT_LT(turns, 6);
    for (const Choice& c : e.choices) EXPECT_FALSE(c.macro);
}

TEST(lsystem_Expand, PredictedLengthBoundsEveryChoice) {
    Definition d = withProduction("FZ", 5);
    d.productions['Z'].push_back({"F[Z]Z", SymbolType::None, 1});
    const std::vector<uint64_t> predicted = predictLengths(d, 5);
    // The worst case takes F[Z]Z at every Z: 2^k tips, lengths 1, 5, 13, 29, 61, 125.
    EXPECT_EQ(predicted, (std::vector<uint64_t>{1, 5, 13, 29, 61, 125}));
    for (uint32_t seed = 0; seed < 50; ++seed) {
        d.seed = seed;
        const Expansion e = expand(d);
        for (size_t k = 0; k < e.lengths.size(); ++k) EXPECT_LE(e.lengths[k], predicted[k]);
    }
}

TEST(lsystem_Expand, ExpansionsPastTheLimitFailBeforeAnyWork) {
    const Definition d = withProduction("ZZ", 40);
    try {
        expand(d);
        FAIL() << "no LimitError";
    } catch (const LimitError& error) {
        EXPECT_EQ(error.limit, "maxExpansions");
        EXPECT_EQ(error.amount, 40u);
        EXPECT_EQ(error.cap, 16u);
    }
}

TEST(lsystem_Expand, PredictedLengthPastTheCapFailsBeforeAllocating) {
    Definition d = withProduction("ZZ", 40);
    d.limits.maxExpansions = 64;
    try {
        expand(d);
        FAIL() << "no LimitError";
    } catch (const LimitError& error) {
        EXPECT_EQ(error.limit, "maxSymbols");
        EXPECT_EQ(error.amount, uint64_t(1) << 25); // the first pass past 2^24
        EXPECT_EQ(error.cap, uint64_t(1) << 24);
        EXPECT_NE(std::string(error.what()).find("25 expansions"), std::string::npos) << error.what();
    }
    d.expansions = 24; // exactly the cap
    d.limits.maxSymbols = uint64_t(1) << 20;
    EXPECT_THROW(expand(d), LimitError);
    d.expansions = 20;
    EXPECT_EQ(expand(d).symbols.size(), uint64_t(1) << 20);
}

TEST(lsystem_Expand, HugeGrammarsSaturateThePrediction) {
    Definition d = withProduction("ZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZZ", 64);
    EXPECT_EQ(predictLengths(d, 64).back(), UINT64_MAX);
}

TEST(lsystem_Expand, SegmentsPastTheLimitFail) {
    Definition d = thesisDefinition();
    d.limits.maxSegments = 3;
    EXPECT_NO_THROW(interpret(d, "FFF"));
    EXPECT_THROW(interpret(d, "FFFF"), LimitError);
}

TEST(lsystem_Expand, NestingIsPredictedAndCapped) {
    Definition d = withProduction("F[Z][C]", 10);
    d.macros['C'] = {{"F[[RFZ]]", SymbolType::Tunnel, 1}, {"FZ", SymbolType::Tunnel, 1}};
    EXPECT_EQ(predictDepth(d, 10), 30u); // 3 levels per pass: [ plus C's two
    d.limits.maxDepth = 29;
    try {
        expand(d);
        FAIL() << "no LimitError";
    } catch (const LimitError& error) {
        EXPECT_EQ(error.limit, "maxDepth");
        EXPECT_EQ(error.amount, 30u);
    }
    d.limits.maxDepth = 3;
    EXPECT_NO_THROW(interpret(d, "F[[[F]]]"));
    EXPECT_THROW(interpret(d, "F[[[[F]]]]"), LimitError);
}

TEST(lsystem_Expand, InvalidDefinitionsAreUserErrors) {
    EXPECT_THROW(expand(withProduction("F[Z", 1)), UserError);
    EXPECT_THROW(expand(withProduction("FXZ", 1)), UserError);
    Definition d = withProduction("FZ", 1);
    d.params.angle = 200;
    EXPECT_THROW(expand(d), UserError);
}

Definition balancedRooms(bool balanced) {
    Definition d = thesisDefinition(std::string(200, 'X'));
    d.selection = Selection::Thesis;
    d.macros['X'] = {{"FZ", SymbolType::Tunnel, 1}, {"BFSZ", SymbolType::Room, 1}};
    if (balanced) d.balanced = BalancedMode{1.0};
    return d;
}

// Tunnels minus rooms over each prefix of the choices: the largest excursion from 0.
int largestImbalance(const Expansion& e) {
    int difference = 0, largest = 0;
    for (const Choice& c : e.choices) {
        difference += c.alternative == 0 ? 1 : -1;
        largest = std::max(largest, std::abs(difference));
    }
    return largest;
}

TEST(lsystem_Expand, BalancedModeAlternatesTunnelsAndRooms) {
    const Expansion e = expand(balancedRooms(true), {.recordChoices = true});
    ASSERT_EQ(e.choices.size(), 200u);
    // With delta 1 under the thesis rule the running offset b = delta * (tunnels - rooms) forces
    // the other type as soon as |b| reaches 1, so the counts never drift apart by more than one.
    EXPECT_EQ(largestImbalance(e), 1);
    EXPECT_GT(largestImbalance(expand(balancedRooms(false), {.recordChoices = true})), 3);
}

TEST(lsystem_Expand, BalancedModeHasNoEffectWhenAllSubstitutesShareAType) {
    for (Selection rule : {Selection::Thesis, Selection::Weighted}) {
        Definition d = thesisDefinition(std::string(100, 'X'));
        d.selection = rule;
        d.macros['X'] = {{"FZ", SymbolType::Tunnel, 1}, {"RFZ", SymbolType::Tunnel, 2}};
        const std::string plain = expand(d).symbols;
        d.balanced = BalancedMode{0.75};
        EXPECT_EQ(expand(d).symbols, plain);
    }
}

TEST(lsystem_Expand, TargetModeTurnsTowardTheTarget) {
    for (double side : {1.0, -1.0}) {
        for (uint32_t seed = 0; seed < 20; ++seed) {
            Definition d = thesisDefinition("CC");
            d.selection = Selection::Thesis;
            d.seed = seed;
            d.macros['C'] = {{"RFZ", SymbolType::Tunnel, 1}, {"LFZ", SymbolType::Tunnel, 1}};
            d.target = TargetMode{{0, 0, 100 * side}, 1.0};
            // Turning toward the target both closes the distance and faces it: the gap is > 1.
            EXPECT_EQ(expand(d).symbols, side > 0 ? "RFZRFZ" : "LFZLFZ") << seed;
        }
    }
}

TEST(lsystem_Expand, TargetModeBiasesWeightedSampling) {
    size_t toward = 0;
    for (uint32_t seed = 0; seed < 400; ++seed) {
        Definition d = thesisDefinition("C");
        d.seed = seed;
        d.macros['C'] = {{"RFZ", SymbolType::Tunnel, 1}, {"LFZ", SymbolType::Tunnel, 1}};
        d.target = TargetMode{{0, 0, 100}, 1.0};
        toward += expand(d).symbols == "RFZ";
    }
    // exp(1.41) / (1 + exp(1.41)) = 0.80.
    EXPECT_NEAR(double(toward) / 400, 0.80, 0.06);
}

} // namespace
} // namespace voxc::lsystem
