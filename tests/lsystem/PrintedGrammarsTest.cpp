// The paper's printed grammars (2), (3), (4), (7), (8): strings, lengths, turtle positions,
// segments and endpoints as computed in the spec (lsystem-spec.md §3, §10 tests 1-3).
#include "TestDefinitions.h"
#include "voxc/generators/lsystem/Expand.h"
#include "voxc/generators/lsystem/Turtle.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/common.hpp>
#include <gtest/gtest.h>
#include <set>
#include <tuple>

namespace voxc::lsystem {
namespace {

using test::expectNear;
using test::withProduction;

const double kHalfRoot2 = std::sqrt(0.5);

size_t countOf(const std::string& s, char c) { return size_t(std::count(s.begin(), s.end(), c)); }

Skeleton run(const Definition& d) {
    const Expansion e = expand(d);
    return interpret(d, e.symbols, e.types);
}

TEST(lsystem_PrintedGrammars, Grammar2StringIsRFToTheNThenZ) {
    for (uint32_t n = 0; n <= 8; ++n) {
        const Expansion e = expand(withProduction("RFZ", n));
        std::string expected;
        for (uint32_t i = 0; i < n; ++i) expected += "RF";
        EXPECT_EQ(e.symbols, expected + "Z");
        EXPECT_EQ(e.symbols.size(), 2 * n + 1);
    }
}

TEST(lsystem_PrintedGrammars, Grammar2DrawsAnOctagonOfSideOne) {
    expectNear(run(withProduction("RFZ", 1)).finalPosition, {kHalfRoot2, 0, kHalfRoot2}, 1e-9);
    expectNear(run(withProduction("RFZ", 2)).finalPosition, {kHalfRoot2, 0, 1 + kHalfRoot2}, 1e-9);
    expectNear(run(withProduction("RFZ", 3)).finalPosition, {0, 0, 1 + std::sqrt(2.0)}, 1e-9);
    expectNear(run(withProduction("RFZ", 3)).finalPosition, {0, 0, 2.414214});
    expectNear(run(withProduction("RFZ", 4)).finalPosition, {-1, 0, 2.414214});
    expectNear(run(withProduction("RFZ", 7)).finalPosition, {-1, 0, 0});
    const Skeleton octagon = run(withProduction("RFZ", 8));
    expectNear(octagon.finalPosition, {0, 0, 0}, 1e-9);
    double farthest = 0;
    for (const Segment& s : octagon.segments) farthest = std::max(farthest, glm::length(s.to));
    EXPECT_NEAR(farthest, 1 / std::sin(std::acos(-1.0) / 8), 1e-9);
    EXPECT_NEAR(farthest, 2.613126, 1e-6);
    ASSERT_EQ(octagon.endpoints.size(), 1u);
}

TEST(lsystem_PrintedGrammars, Grammar3LengthsCountsAndEndpoints) {
    const uint64_t lengths[] = {18, 86, 358, 1446, 5798};
    const size_t moves[] = {5, 25, 105, 425, 1705};
    const size_t endpoints[] = {2, 9, 37, 149, 597};
    for (uint32_t n = 1; n <= 5; ++n) {
        const Definition d = withProduction("FZ[RFZ]FZ[LFZ[RF]]", n);
        const Expansion e = expand(d);
        EXPECT_EQ(e.symbols.size(), lengths[n - 1]) << n;
        EXPECT_EQ(predictLengths(d, n).back(), lengths[n - 1]) << n;
        EXPECT_EQ(countOf(e.symbols, 'F'), moves[n - 1]) << n;
        EXPECT_EQ(countOf(e.symbols, 'Z'), size_t(1) << (2 * n)) << n;
        EXPECT_EQ(countOf(e.symbols, '['), ((size_t(1) << (2 * n)) - 1)) << n;
        const Skeleton s = interpret(d, e.symbols, e.types);
        EXPECT_EQ(s.segments.size(), moves[n - 1]) << n;
        EXPECT_EQ(s.endpoints.size(), endpoints[n - 1]) << n;
    }
    expectNear(run(withProduction("FZ[RFZ]FZ[LFZ[RF]]", 5)).finalPosition, {62, 0, 0}, 1e-9);
}

TEST(lsystem_PrintedGrammars, Grammar3TwoExpansionsString) {
    EXPECT_EQ(expand(withProduction("FZ[RFZ]FZ[LFZ[RF]]", 2)).symbols,
              "FFZ[RFZ]FZ[LFZ[RF]][RFFZ[RFZ]FZ[LFZ[RF]]]FFZ[RFZ]FZ[LFZ[RF]][LFFZ[RFZ]FZ[LFZ[RF]][RF]]");
}

TEST(lsystem_PrintedGrammars, Grammar3OneExpansionSegmentsAndEndpoints) {
    const Skeleton s = run(withProduction("FZ[RFZ]FZ[LFZ[RF]]", 1));
    const glm::dvec3 expected[][2] = {{{0, 0, 0}, {1, 0, 0}},
                                      {{1, 0, 0}, {1 + kHalfRoot2, 0, kHalfRoot2}},
                                      {{1, 0, 0}, {2, 0, 0}},
                                      {{2, 0, 0}, {2 + kHalfRoot2, 0, -kHalfRoot2}},
                                      {{2 + kHalfRoot2, 0, -kHalfRoot2}, {3 + kHalfRoot2, 0, -kHalfRoot2}}};
    ASSERT_EQ(s.segments.size(), 5u);
    for (size_t i = 0; i < 5; ++i) {
        expectNear(s.segments[i].from, expected[i][0], 1e-9);
        expectNear(s.segments[i].to, expected[i][1], 1e-9);
    }
    ASSERT_EQ(s.endpoints.size(), 2u);
    expectNear(s.endpoints[0].position, {1.707107, 0, 0.707107});
    expectNear(s.endpoints[1].position, {3.707107, 0, -0.707107});
}

TEST(lsystem_PrintedGrammars, Grammar4MacrosAreSubstitutedBeforeWriting) {
    Definition d = withProduction("C[H]", 1);
    d.macros['C'] = {{"FLFLF", SymbolType::Tunnel, 1}};
    d.macros['H'] = {{"FUFFDF", SymbolType::Tunnel, 1}};
    const Expansion e = expand(d);
    EXPECT_EQ(e.symbols, "FLFLF[FUFFDF]");
    // Substituted symbols carry their substitute's type; the production's own brackets its type.
    for (size_t i = 0; i < e.symbols.size(); ++i)
        EXPECT_EQ(e.types[i], (e.symbols[i] == '[' || e.symbols[i] == ']') ? SymbolType::None : SymbolType::Tunnel) << i;
    const Skeleton s = interpret(d, e.symbols, e.types);
    ASSERT_EQ(s.segments.size(), 7u);
    EXPECT_EQ(s.segments[0].type, SymbolType::Tunnel);
    expectNear(s.segments[2].to, {1.707107, 0, -1.707107});
    expectNear(s.segments[4].to, {1.707107, 0.707107, -3.414214});
    expectNear(s.segments[6].to, {1.707107, 1.414214, -5.121320});
    ASSERT_EQ(s.endpoints.size(), 1u);
    expectNear(s.endpoints[0].position, {1.707107, 1.414214, -5.121320});
    expectNear(s.finalPosition, {1.707107, 0, -1.707107});
}

TEST(lsystem_PrintedGrammars, MacrosOfTheAxiomAreResolvedBeforeTheFirstExpansion) {
    Definition d = test::thesisDefinition("C");
    d.macros['C'] = {{"FLFLFZ", SymbolType::Tunnel, 1}};
    EXPECT_EQ(expand(d).symbols, "FLFLFZ");
}

TEST(lsystem_PrintedGrammars, Grammars7And8LengthsAndEndpoints) {
    struct Case {
        const char* rhs;
        size_t length, length2, moves2, tips2, endpoints1, endpoints2;
    } cases[] = {{"FF[RFLFRF[LFFFFZ]FZ]F[LFZ]", 26, 101, 48, 9, 3, 9},
                 {"FF[RFZ]F[LFLFRFFLFRFZ]", 22, 64, 30, 4, 2, 4},
                 {"FF[RFLFRF[LFFFFZ]FZ]F[LFLFRFFLFRFZ]", 35, 137, 68, 9, 3, 9},
                 {"FF[RFZ]F[LFZ]", 13, 37, 15, 4, 2, 4}};
    for (const Case& c : cases) {
        EXPECT_EQ(std::string(c.rhs).size(), c.length);
        const Expansion twice = expand(withProduction(c.rhs, 2));
        EXPECT_EQ(twice.symbols.size(), c.length2) << c.rhs;
        EXPECT_EQ(countOf(twice.symbols, 'F'), c.moves2) << c.rhs;
        EXPECT_EQ(countOf(twice.symbols, 'Z'), c.tips2) << c.rhs;
        EXPECT_EQ(run(withProduction(c.rhs, 1)).endpoints.size(), c.endpoints1) << c.rhs;
        EXPECT_EQ(run(withProduction(c.rhs, 2)).endpoints.size(), c.endpoints2) << c.rhs;
    }
}

// ABOP Fig. 1.10: the 3D Hilbert curve runs unchanged on the abop turtle. After n expansions it
// visits every point of a 2^n cube exactly once with unit steps, whatever the frame's handedness.
TEST(lsystem_PrintedGrammars, AbopHilbertCurveFillsTheCube) {
    Definition d = test::thesisDefinition("A");
    d.turtle = TurtleKind::Abop;
    d.params.angle = 90;
    d.productions['A'] = {{"B-F+CFC+F-D&F^D-F+&&CFC+F+B//", SymbolType::None, 1}};
    d.productions['B'] = {{"A&F^CFB^F^D^^-F-D^|F^B|FC^F^A//", SymbolType::None, 1}};
    d.productions['C'] = {{"|D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//", SymbolType::None, 1}};
    d.productions['D'] = {{"|CFB-F+B|FA&F^A&&FB-F+B|FC//", SymbolType::None, 1}};
    for (uint32_t n = 1; n <= 3; ++n) {
        d.expansions = n;
        const Skeleton s = run(d);
        const size_t points = size_t(1) << (3 * n);
        ASSERT_EQ(s.segments.size(), points - 1) << n;
        std::set<std::tuple<long, long, long>> visited{{0, 0, 0}};
        glm::dvec3 low(0.0), high(0.0);
        for (const Segment& segment : s.segments) {
            EXPECT_NEAR(glm::length(segment.to - segment.from), 1.0, 1e-9);
            const glm::dvec3 p = glm::round(segment.to);
            EXPECT_NEAR(glm::length(segment.to - p), 0.0, 1e-9);
            visited.insert({std::lround(p.x), std::lround(p.y), std::lround(p.z)});
            low = glm::min(low, p), high = glm::max(high, p);
        }
        EXPECT_EQ(visited.size(), points) << n;
        EXPECT_EQ(high - low, glm::dvec3(double((1 << n) - 1))) << n;
    }
}

} // namespace
} // namespace voxc::lsystem
