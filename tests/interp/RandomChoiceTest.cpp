// Random choices: weighted ties, firing probability, determinism and hashing by world position.
// Statistical checks use a fixed seed (so they are deterministic) and a 5-sigma binomial bound.
#include "ProgramText.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/stages/Pipeline.h"

#include <cmath>
#include <gtest/gtest.h>

namespace voxc {
namespace random_choice_test {

using test::makeGrammar;
using test::makeProgram;
using test::makeRule;

constexpr glm::ivec3 kPlane{64, 64, 1}; // 4096 anchors for a 1x1x1 window

size_t countEqual(const DenseGrid& grid, float value) {
    size_t n = 0;
    for (float d : grid.data()) n += d == value;
    return n;
}

void expectFraction(size_t hits, size_t trials, double p) {
    const double fraction = double(hits) / double(trials);
    const double sigma = std::sqrt(p * (1.0 - p) / double(trials));
    EXPECT_NEAR(fraction, p, 5.0 * sigma) << hits << " of " << trials;
}

TEST(interp_Random, EqualPriorityTiesAreDrawnByWeight) {
    Rule one = makeRule("one", {"IGN"}, {"SET 1"});
    Rule three = makeRule("three", {"IGN"}, {"SET 2"});
    test::setWeight(one, 1.0f);
    test::setWeight(three, 3.0f);
    const Program program = makeProgram(kPlane, {makeGrammar("g", kPlane, {one, three})}, 12345);
    const DenseGrid grid = interpret(program);
    const size_t ones = countEqual(grid, 1.0f), twos = countEqual(grid, 2.0f);
    EXPECT_EQ(ones + twos, grid.data().size()); // every anchor fired exactly one of them
    expectFraction(twos, grid.data().size(), 0.75);
}

TEST(interp_Random, ProbabilityGatesTheChosenRule) {
    Rule rule = makeRule("sometimes", {"IGN"}, {"SET 1"});
    test::setProbability(rule, 0.25f);
    const Program program = makeProgram(kPlane, {makeGrammar("g", kPlane, {rule})}, 777);
    const DenseGrid grid = interpret(program);
    expectFraction(countEqual(grid, 1.0f), grid.data().size(), 0.25);
}

TEST(interp_Random, ProbabilityZeroAndOne) {
    Rule never = makeRule("never", {"IGN"}, {"SET 1"});
    test::setProbability(never, 0.0f);
    EXPECT_EQ(countEqual(interpret(makeProgram(kPlane, {makeGrammar("g", kPlane, {never})}, 1)), 1.0f), 0u);
    Rule always = makeRule("always", {"IGN"}, {"SET 1"});
    EXPECT_EQ(countEqual(interpret(makeProgram(kPlane, {makeGrammar("g", kPlane, {always})}, 1)), 1.0f),
              size_t(kPlane.x * kPlane.y));
}

Program noisyProgram(uint32_t seed, glm::ivec3 size, glm::ivec3 origin) {
    Rule up = makeRule("up", {"IGN"}, {"ADD 1"});
    Rule down = makeRule("down", {"IGN"}, {"ADD -1"});
    test::setProbability(down, 0.5f);
    Rule pair = makeRule("pair", {"IGN, IGN"}, {"ADD 0.5, NOP"});
    test::setProbability(pair, 0.5f);
    Grammar g = makeGrammar("noisy", size, {up, down, pair});
    g.iterations = 3;
    Program program = makeProgram(size, {g}, seed);
    program.world.origin = origin;
    return program;
}

TEST(interp_Random, SameSeedSameGridDifferentSeedDifferentGrid) {
    const glm::ivec3 size{16, 8, 4};
    const DenseGrid a = interpret(noisyProgram(5, size, {0, 0, 0}));
    EXPECT_EQ(interpret(noisyProgram(5, size, {0, 0, 0})).data(), a.data());
    EXPECT_NE(interpret(noisyProgram(6, size, {0, 0, 0})).data(), a.data());
    EXPECT_NE(interpret(noisyProgram(5, size, {1, 0, 0})).data(), a.data());
}

// Random draws hash the anchor's world coordinate: a grid that covers the right half of another
// grid's world makes the same choices there (1x1 windows, so the halves do not interact).
TEST(interp_Random, DrawsDependOnWorldNotGridPosition) {
    Rule rule = makeRule("sometimes", {"IGN"}, {"ADD 1"});
    test::setProbability(rule, 0.5f);
    Program whole = makeProgram({32, 1, 1}, {makeGrammar("g", {32, 1, 1}, {rule})}, 9);
    whole.grammars[0].iterations = 4;
    whole.world.origin = {-16, 100, -7};
    Program half = makeProgram({16, 1, 1}, {makeGrammar("g", {16, 1, 1}, {rule})}, 9);
    half.grammars[0].iterations = 4;
    half.world.origin = {0, 100, -7};
    const DenseGrid a = interpret(whole);
    const DenseGrid b = interpret(half);
    for (int x = 0; x < 16; ++x) EXPECT_EQ(b.at({x, 0, 0}), a.at({x + 16, 0, 0})) << x;
}

} // namespace random_choice_test
} // namespace voxc
