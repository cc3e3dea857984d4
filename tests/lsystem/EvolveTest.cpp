// Random production rules (lsystem-spec.md §2.5; §10 test 12), crossover by bracket index
// (§8, grammars (7) -> (8); §10 test 9) and mutation.
#include "TestDefinitions.h"
#include "voxc/generators/lsystem/Evolve.h"
#include "voxc/generators/lsystem/Expand.h"
#include "voxc/generators/lsystem/Turtle.h"

#include <gtest/gtest.h>
#include <set>

namespace voxc::lsystem {
namespace {

RandomRuleParams paperParams(Selection selection) {
    RandomRuleParams params;
    params.weights = {{'C', 0}, {'H', 0.5}, {'I', 0}, {'Q', 0.25}, {'T', -1}};
    params.selection = selection;
    return params;
}

TEST(lsystem_RandomRules, ThousandSeedsKeepEveryPrintedProperty) {
    for (Selection selection : {Selection::Thesis, Selection::Weighted}) {
        const RandomRuleParams params = paperParams(selection);
        std::set<std::string> distinct;
        for (uint32_t seed = 0; seed < 1000; ++seed) {
            const std::string rule = randomProduction(params, seed);
            distinct.insert(rule);
            size_t macros = 0;
            int depth = 0, pairs = 0;
            for (char c : rule) {
                if (c == '[') {
                    ++depth, ++pairs;
                } else if (c == ']') {
                    ASSERT_GE(--depth, 0) << rule;
                } else {
                    ++macros;
                    ASSERT_TRUE(params.weights.count(c)) << rule;
                }
            }
            EXPECT_EQ(macros, 6u) << rule;
            EXPECT_EQ(depth, 0) << rule;
            EXPECT_GE(pairs, 1) << rule;
            EXPECT_EQ(rule.find("[]"), std::string::npos) << rule;
            EXPECT_NE(rule.front(), '[') << rule;
            EXPECT_EQ(rule.find('T'), std::string::npos) << rule; // weight -1
        }
        EXPECT_GT(distinct.size(), 500u);
    }
}

// Random rules drive a real expansion: with the macros' substitutes they expand and draw.
TEST(lsystem_RandomRules, RandomRulesExpandAndDraw) {
    const RandomRuleParams params = paperParams(Selection::Weighted);
    for (uint32_t seed = 0; seed < 200; ++seed) {
        Definition d = test::withProduction(randomProduction(params, seed), 2);
        for (const auto& [macro, weight] : params.weights)
            d.macros[macro] = {{"FFZ", SymbolType::Tunnel, 1}, {"RFZ", macro == 'Q' ? SymbolType::Room : SymbolType::Tunnel, 1}};
        d.seed = seed;
        const Expansion e = expand(d);
        // Each macro draws at least one F: 6 after the first pass, 6 + 36 after the second.
        EXPECT_GE(interpret(d, e.symbols, e.types).segments.size(), 42u) << d.productions['Z'][0].text;
    }
}

TEST(lsystem_RandomRules, MacroCountFollowsItsRangeAndSeedsReproduce) {
    RandomRuleParams params = paperParams(Selection::Weighted);
    params.minMacros = 2;
    params.maxMacros = 5;
    std::set<size_t> counts;
    for (uint32_t seed = 0; seed < 200; ++seed) {
        const std::string rule = randomProduction(params, seed, 3);
        EXPECT_EQ(rule, randomProduction(params, seed, 3));
        counts.insert(rule.size() - size_t(std::count(rule.begin(), rule.end(), '[')) * 2);
    }
    EXPECT_EQ(counts, (std::set<size_t>{2, 3, 4, 5}));
    EXPECT_EQ(randomProduction([] { RandomRuleParams p; p.weights = {{'Q', 1}}; p.bracketChance = 0; return p; }(), 1),
              "QQQQQ[Q]");
}

TEST(lsystem_RandomRules, BadParametersAreUserErrors) {
    RandomRuleParams params = paperParams(Selection::Thesis);
    params.minMacros = 1;
    EXPECT_THROW(randomProduction(params, 0), UserError);
    params = paperParams(Selection::Thesis);
    params.weights = {{'T', -1}};
    EXPECT_THROW(randomProduction(params, 0), UserError);
    params = paperParams(Selection::Thesis);
    params.bracketChance = 1.5;
    EXPECT_THROW(randomProduction(params, 0), UserError);
}

TEST(lsystem_Crossover, Grammars7Give8Exactly) {
    const std::string a = "FF[RFLFRF[LFFFFZ]FZ]F[LFZ]", b = "FF[RFZ]F[LFLFRFFLFRFZ]";
    const auto [c, d] = crossover(a, 3, b, 2);
    EXPECT_EQ(c, "FF[RFLFRF[LFFFFZ]FZ]F[LFLFRFFLFRFZ]");
    EXPECT_EQ(d, "FF[RFZ]F[LFZ]");
    EXPECT_EQ(a.size() + b.size(), 26u + 22u);
    EXPECT_EQ(c.size() + d.size(), 35u + 13u);
}

TEST(lsystem_Crossover, BracketsAreNumberedByOpeningOrder) {
    const auto pairs = bracketPairs("FF[RFLFRF[LFFFFZ]FZ]F[LFZ]");
    ASSERT_EQ(pairs.size(), 3u);
    EXPECT_EQ(pairs[0], (std::pair<size_t, size_t>{2, 19}));
    EXPECT_EQ(pairs[1], (std::pair<size_t, size_t>{9, 16}));
    EXPECT_EQ(pairs[2], (std::pair<size_t, size_t>{21, 25}));
    // A nested bracket exchanged with an outer one.
    EXPECT_EQ(crossover("A[B[C]]", 2, "[D]", 1), (std::pair<std::string, std::string>{"A[B[D]]", "[C]"}));
}

TEST(lsystem_Crossover, IndicesOutOfRangeAreUserErrors) {
    EXPECT_THROW(crossover("F[F]", 2, "F[F]", 1), UserError);
    EXPECT_THROW(crossover("FF", 1, "F[F]", 1), UserError);
    EXPECT_THROW(crossover("F[F", 1, "F[F]", 1), UserError);
    EXPECT_THROW(randomCrossoverIndices("FF", "F[F]", 1, 0, 0), UserError);
}

TEST(lsystem_Crossover, RandomIndicesAreInRangeAndReproducible) {
    const std::string a = "FF[RFLFRF[LFFFFZ]FZ]F[LFZ]", b = "FF[RFZ]F[LFLFRFFLFRFZ]";
    std::set<std::pair<size_t, size_t>> seen;
    for (uint32_t child = 0; child < 200; ++child) {
        const auto indices = randomCrossoverIndices(a, b, 9, 1, child);
        EXPECT_EQ(indices, randomCrossoverIndices(a, b, 9, 1, child));
        EXPECT_GE(indices.first, 1u);
        EXPECT_LE(indices.first, 3u);
        EXPECT_GE(indices.second, 1u);
        EXPECT_LE(indices.second, 2u);
        seen.insert(indices);
    }
    EXPECT_EQ(seen.size(), 6u);
}

Definition macroDefinition() {
    Definition d = test::withProduction("QIH[CT[T]]", 2);
    for (char m : std::string("CHIQT")) d.macros[m] = {{"FZ", SymbolType::Tunnel, 1}, {"RFZ", SymbolType::Tunnel, 0.5}};
    return d;
}

TEST(lsystem_Mutation, EveryKindOccursAndEveryResultIsValidAndReproducible) {
    const Definition d = macroDefinition();
    std::set<MutationKind> kinds;
    for (uint32_t child = 0; child < 200; ++child) {
        Mutation mutation;
        const Definition m = mutate(d, 4, 1, child, &mutation);
        kinds.insert(mutation.kind);
        EXPECT_TRUE(checkDefinition(m).empty()) << mutation.description;
        EXPECT_FALSE(mutation.description.empty());
        const Definition again = mutate(d, 4, 1, child);
        EXPECT_EQ(again.productions.at('Z')[0].text, m.productions.at('Z')[0].text);
        const std::string& before = d.productions.at('Z')[0].text;
        const std::string& after = m.productions.at('Z')[0].text;
        switch (mutation.kind) {
        case MutationKind::SwapMacro:
            EXPECT_EQ(after.size(), before.size());
            EXPECT_NE(after, before);
            break;
        case MutationKind::InsertBrackets: EXPECT_EQ(after.size(), before.size() + 2); break;
        case MutationKind::DeleteBrackets: EXPECT_EQ(after.size(), before.size() - 2); break;
        case MutationKind::PerturbWeight: EXPECT_EQ(after, before); break;
        }
    }
    EXPECT_EQ(kinds.size(), 4u);
}

TEST(lsystem_Mutation, NothingToMutateIsAUserError) {
    EXPECT_THROW(mutate(test::thesisDefinition(), 0, 0, 0), UserError);
}

TEST(lsystem_Evolution, NextGenerationCrossesPicksAndIsReproducible) {
    Definition a = test::withProduction("FF[RFLFRF[LFFFFZ]FZ]F[LFZ]", 2), b = test::withProduction("FF[RFZ]F[LFLFRFFLFRFZ]", 2);
    const std::vector<Definition> children = nextGeneration({a, b}, 6, 17, 1);
    const std::vector<Definition> again = nextGeneration({a, b}, 6, 17, 1);
    ASSERT_EQ(children.size(), 6u);
    std::set<uint32_t> seeds;
    for (size_t k = 0; k < 6; ++k) {
        EXPECT_EQ(children[k].productions.at('Z')[0].text, again[k].productions.at('Z')[0].text);
        EXPECT_EQ(children[k].seed, again[k].seed);
        EXPECT_TRUE(checkDefinition(children[k]).empty());
        EXPECT_NO_THROW(expand(children[k]));
        seeds.insert(children[k].seed);
    }
    EXPECT_EQ(seeds.size(), 6u);
}

} // namespace
} // namespace voxc::lsystem
