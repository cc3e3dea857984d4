// The shared execution order: sweeps, phases, anchors and rule choice (voxc/program/Semantics.h).
#include "ProgramText.h"
#include "voxc/program/Random.h"
#include "voxc/program/Semantics.h"

#include <gtest/gtest.h>
#include <map>
#include <set>
#include <tuple>

namespace voxc {
namespace {

using test::makeGrammar;
using test::makeRule;

Rule ignRule(const char* name, int x, int y) {
    std::vector<std::string> symbol(static_cast<size_t>(y));
    std::vector<std::string> transform(static_cast<size_t>(y));
    for (int j = 0; j < y; ++j)
        for (int i = 0; i < x; ++i) {
            symbol[size_t(j)] += i ? ", IGN" : "IGN";
            transform[size_t(j)] += i ? ", NOP" : "NOP";
        }
    return makeRule(name, symbol, transform);
}

TEST(program_Semantics, SweepsLargestVolumeFirstThenDeclarationOrder) {
    const Grammar g = makeGrammar("g", {8, 8, 1},
                                  {ignRule("a1", 1, 1), ignRule("b2x1", 2, 1), ignRule("c1x2", 1, 2),
                                   ignRule("d3x3", 3, 3), ignRule("e2x1", 2, 1)});
    const std::vector<Sweep> sweeps = orderSweeps(g);
    ASSERT_EQ(sweeps.size(), 4u);
    EXPECT_EQ(sweeps[0].window, glm::ivec3(3, 3, 1));
    EXPECT_EQ(sweeps[1].window, glm::ivec3(2, 1, 1)); // declared before the equal-volume 1x2
    EXPECT_EQ(sweeps[1].rules, (std::vector<uint32_t>{1, 4}));
    EXPECT_EQ(sweeps[2].window, glm::ivec3(1, 2, 1));
    EXPECT_EQ(sweeps[3].window, glm::ivec3(1, 1, 1));
    EXPECT_EQ(sweeps[0].anchorCount, glm::ivec3(6, 6, 1));
    EXPECT_EQ(sweeps[0].phaseCount, glm::ivec3(3, 3, 1));
}

TEST(program_Semantics, WindowThatDoesNotFitHasNoAnchors) {
    Grammar g = makeGrammar("g", {8, 8, 1}, {ignRule("big", 3, 3)});
    g.boundsMin = {0, 0, 0};
    g.boundsMax = {2, 8, 1};
    const Sweep sweep = orderSweeps(g).front();
    EXPECT_EQ(sweep.anchorCount.x, 0);
    for (int p = 0; p < sweep.phases(); ++p) EXPECT_EQ(phaseAnchors(g, sweep, p).count.x, 0);
}

TEST(program_Semantics, PhaseResidueIsXFastest) {
    Sweep sweep;
    sweep.phaseCount = {2, 3, 2};
    EXPECT_EQ(phaseResidue(sweep, 0), glm::ivec3(0, 0, 0));
    EXPECT_EQ(phaseResidue(sweep, 1), glm::ivec3(1, 0, 0));
    EXPECT_EQ(phaseResidue(sweep, 2), glm::ivec3(0, 1, 0));
    EXPECT_EQ(phaseResidue(sweep, 6), glm::ivec3(0, 0, 1));
    EXPECT_EQ(phaseResidue(sweep, 11), glm::ivec3(1, 2, 1));
}

// Over strides and bounds: the phases partition exactly the anchors boundsMin + n*stride whose
// window fits, and no two windows of one phase overlap.
TEST(program_Semantics, PhasesPartitionAnchorsWithoutOverlap) {
    for (int stride = 1; stride <= 4; ++stride) {
        for (int window = 1; window <= 4; ++window) {
            Grammar g = makeGrammar("g", {13, 11, 1}, {ignRule("r", window, window)});
            g.stride = {stride, stride, 1};
            g.boundsMin = {1, 2, 0};
            g.boundsMax = {13, 10, 1};
            const Sweep sweep = orderSweeps(g).front();
            std::set<std::pair<int, int>> expected;
            for (int y = g.boundsMin.y; y + window <= g.boundsMax.y; y += stride)
                for (int x = g.boundsMin.x; x + window <= g.boundsMax.x; x += stride) expected.insert({x, y});
            std::set<std::pair<int, int>> seen;
            for (int p = 0; p < sweep.phases(); ++p) {
                const PhaseAnchors a = phaseAnchors(g, sweep, p);
                std::map<std::pair<int, int>, int> covered;
                for (int j = 0; j < a.count.y; ++j)
                    for (int i = 0; i < a.count.x; ++i) {
                        const glm::ivec3 anchor = a.start + glm::ivec3(i, j, 0) * a.step;
                        EXPECT_TRUE(seen.insert({anchor.x, anchor.y}).second) << "anchor in two phases";
                        for (int dy = 0; dy < window; ++dy)
                            for (int dx = 0; dx < window; ++dx)
                                EXPECT_EQ(++covered[std::make_pair(anchor.x + dx, anchor.y + dy)], 1) << "overlap in phase " << p;
                    }
            }
            EXPECT_EQ(seen, expected) << "stride " << stride << " window " << window;
        }
    }
}

TEST(program_Semantics, ChooseRuleNoMatch) {
    const Grammar g = makeGrammar("g", {4, 4, 1}, {ignRule("a", 1, 1)});
    EXPECT_EQ(chooseRule(g, {}, 0, 0, 0, {0, 0, 0}), -1);
}

TEST(program_Semantics, ChooseRuleHighestPriorityWins) {
    Grammar g = makeGrammar("g", {4, 4, 1}, {ignRule("low", 1, 1), ignRule("high", 1, 1), ignRule("mid", 1, 1)});
    g.rules[1].priority = 5;
    g.rules[2].priority = 2;
    test::setWeight(g.rules[0], 1000.0f);
    for (int x = 0; x < 64; ++x) {
        EXPECT_EQ(chooseRule(g, {0, 1, 2}, 7, 0, 0, {x, 0, 0}), 1);
        EXPECT_EQ(chooseRule(g, {0, 2}, 7, 0, 0, {x, 0, 0}), 2);
    }
}

TEST(program_Semantics, ChooseRuleIsAPureFunctionOfItsInputs) {
    Grammar g = makeGrammar("g", {4, 4, 1}, {ignRule("a", 1, 1), ignRule("b", 1, 1)});
    int differs = 0;
    for (int x = 0; x < 64; ++x) {
        const int first = chooseRule(g, {0, 1}, 3, 1, 0, {x, -5, 1 << 20});
        EXPECT_EQ(first, chooseRule(g, {0, 1}, 3, 1, 0, {x, -5, 1 << 20}));
        differs += first != chooseRule(g, {0, 1}, 4, 1, 0, {x, -5, 1 << 20});
    }
    EXPECT_GT(differs, 0);
}

TEST(program_Semantics, AnchorHashSeparatesEveryInput) {
    const uint32_t base = anchorHash(1, 2, 3, {4, 5, 6}, RandomStream::RuleChoice);
    EXPECT_EQ(base, anchorHash(1, 2, 3, {4, 5, 6}, RandomStream::RuleChoice));
    EXPECT_NE(base, anchorHash(0, 2, 3, {4, 5, 6}, RandomStream::RuleChoice));
    EXPECT_NE(base, anchorHash(1, 0, 3, {4, 5, 6}, RandomStream::RuleChoice));
    EXPECT_NE(base, anchorHash(1, 2, 0, {4, 5, 6}, RandomStream::RuleChoice));
    EXPECT_NE(base, anchorHash(1, 2, 3, {0, 5, 6}, RandomStream::RuleChoice));
    EXPECT_NE(base, anchorHash(1, 2, 3, {4, 0, 6}, RandomStream::RuleChoice));
    EXPECT_NE(base, anchorHash(1, 2, 3, {4, 5, 0}, RandomStream::RuleChoice));
    EXPECT_NE(base, anchorHash(1, 2, 3, {4, 5, 6}, RandomStream::Probability));
    EXPECT_EQ(mix32(0u), 0u);
}

} // namespace
} // namespace voxc
