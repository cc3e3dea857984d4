// ValueSet: the interval algebra the checker uses to prove cells can or cannot pass together.
#include "voxc/builtins/ValueSet.h"

#include <gtest/gtest.h>

namespace voxc {
namespace {

struct Expected {
    float lo, hi;
    bool loClosed, hiClosed;
};

void expectIntervals(const ValueSet& set, std::vector<Expected> expected) {
    ASSERT_EQ(set.intervals().size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        const ValueInterval& got = set.intervals()[i];
        EXPECT_EQ(got.lo, expected[i].lo) << i;
        EXPECT_EQ(got.hi, expected[i].hi) << i;
        EXPECT_EQ(got.loClosed, expected[i].loClosed) << i;
        EXPECT_EQ(got.hiClosed, expected[i].hiClosed) << i;
    }
}

constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(program_ValueSet, Constructors) {
    expectIntervals(ValueSet::all(), {{-kInf, kInf, false, false}});
    expectIntervals(ValueSet::point(0.5f), {{0.5f, 0.5f, true, true}});
    expectIntervals(ValueSet::below(1.0f, false), {{-kInf, 1.0f, false, false}});
    expectIntervals(ValueSet::above(0.8f, true), {{0.8f, kInf, true, false}});
    expectIntervals(ValueSet::allBut(0.5f), {{-kInf, 0.5f, false, false}, {0.5f, kInf, false, false}});
}

TEST(program_ValueSet, OpenBoundsMeetingAtOnePointAreDisjoint) {
    EXPECT_TRUE(ValueSet::below(0.5f, false).intersect(ValueSet::above(0.5f, false)).empty());
    EXPECT_TRUE(ValueSet::below(0.5f, true).intersect(ValueSet::above(0.5f, false)).empty());
    EXPECT_TRUE(ValueSet::below(0.5f, false).intersect(ValueSet::above(0.5f, true)).empty());
}

TEST(program_ValueSet, ClosedBoundsMeetingAtOnePointLeaveThePoint) {
    expectIntervals(ValueSet::below(0.5f, true).intersect(ValueSet::above(0.5f, true)), {{0.5f, 0.5f, true, true}});
}

TEST(program_ValueSet, AbsAndPresNeverBothPass) {
    EXPECT_TRUE(ValueSet::point(0.0f).intersect(ValueSet::above(0.0f, false)).empty());
}

TEST(program_ValueSet, AllButSplitsARange) {
    const ValueSet range = ValueSet::above(0.0f, true).intersect(ValueSet::below(1.0f, false));
    expectIntervals(range.intersect(ValueSet::allBut(0.5f)), {{0.0f, 0.5f, true, false}, {0.5f, 1.0f, false, false}});
    EXPECT_TRUE(ValueSet::allBut(0.5f).intersect(ValueSet::point(0.5f)).empty());
}

TEST(program_ValueSet, IntersectionWithAllIsIdentity) {
    expectIntervals(ValueSet::all().intersect(ValueSet::above(0.25f, false)), {{0.25f, kInf, false, false}});
    expectIntervals(ValueSet::point(0.3f).intersect(ValueSet::all()), {{0.3f, 0.3f, true, true}});
}

TEST(program_ValueSet, TighterBoundWins) {
    // GEQ 0.5 & LT 0.5 & GT 0.1 (from the brief's example) is empty; GT 0.1 & LT 0.5 is (0.1, 0.5).
    const ValueSet band = ValueSet::above(0.1f, false).intersect(ValueSet::below(0.5f, false));
    expectIntervals(band, {{0.1f, 0.5f, false, false}});
    EXPECT_TRUE(band.intersect(ValueSet::above(0.5f, true)).empty());
    expectIntervals(ValueSet::above(0.1f, true).intersect(ValueSet::above(0.1f, false)), {{0.1f, kInf, false, false}});
    expectIntervals(ValueSet::below(0.1f, true).intersect(ValueSet::below(0.1f, false)), {{-kInf, 0.1f, false, false}});
}

TEST(program_ValueSet, EmptyStaysEmpty) {
    const ValueSet none = ValueSet::point(1.0f).intersect(ValueSet::point(2.0f));
    EXPECT_TRUE(none.empty());
    EXPECT_TRUE(none.intersect(ValueSet::all()).empty());
    EXPECT_TRUE(ValueSet::all().intersect(none).empty());
}

} // namespace
} // namespace voxc
