// The turtle (lsystem-spec.md §1, §4.3; §10 tests 4-8): full-state brackets, pitch and its
// limit, O/A/B/S with their clamps, `0`, constrained clipping, the ABOP frame.
#include "TestDefinitions.h"
#include "voxc/generators/lsystem/Selection.h"
#include "voxc/generators/lsystem/Turtle.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace voxc::lsystem {
namespace {

using test::expectNear;
using test::thesisDefinition;

Skeleton draw(const std::string& symbols, const Definition& d = thesisDefinition()) { return interpret(d, symbols); }

TEST(lsystem_Turtle, BracketsRestorePositionAndHeading) {
    const Skeleton s = draw("F[RF]F");
    expectNear(s.finalPosition, {2, 0, 0}, 1e-9);
    ASSERT_EQ(s.endpoints.size(), 2u);
    expectNear(s.endpoints[0].position, {1.707107, 0, 0.707107});
    expectNear(s.endpoints[1].position, {2, 0, 0}, 1e-9);
}

TEST(lsystem_Turtle, BracketsRestoreTheAngle) {
    Definition d = thesisDefinition();
    d.params.angleDelta = 5;
    expectNear(draw("F[OORF]F", d).finalPosition, {2, 0, 0}, 1e-9);
    // After the bracket the angle is 45 again: RF turns exactly 45 degrees.
    expectNear(draw("F[OORF]RF", d).finalPosition, {1 + std::sqrt(0.5), 0, std::sqrt(0.5)}, 1e-9);
}

TEST(lsystem_Turtle, BranchesGetIdsAndParents) {
    const Skeleton s = draw("F[RF[LF]]F");
    ASSERT_EQ(s.branches.size(), 3u);
    EXPECT_EQ(s.branches[1].parent, 0u);
    EXPECT_EQ(s.branches[2].parent, 1u);
    ASSERT_EQ(s.segments.size(), 4u);
    EXPECT_EQ(s.segments[0].branch, 0u);
    EXPECT_EQ(s.segments[1].branch, 1u);
    EXPECT_EQ(s.segments[2].branch, 2u);
    EXPECT_EQ(s.segments[3].branch, 0u);
}

TEST(lsystem_Turtle, PitchTurnsPastVertical) {
    expectNear(draw("UUF").finalPosition, {0, 1, 0}, 1e-9);
    expectNear(draw("UUUUF").finalPosition, {-1, 0, 0}, 1e-9);
}

TEST(lsystem_Turtle, PitchLimitClampsTheAccumulator) {
    Definition d = thesisDefinition();
    d.params.pitchLimit = 30;
    expectNear(draw("UUF", d).finalPosition, {0.866025, 0.5, 0});
    expectNear(draw("UUFDF", d).finalPosition, {1.831951, 0.241181, 0});
}

TEST(lsystem_Turtle, AngleAndStepSymbolsWithTheirClamps) {
    Definition d = thesisDefinition();
    d.params.angleDelta = 5;
    d.params.stepDelta = 0.5;
    expectNear(draw("OORF", d).finalPosition, {0.573576, 0, 0.819152});
    expectNear(draw("BF", d).finalPosition, {1.5, 0, 0}, 1e-12);
    const Skeleton stopped = draw("SSSSF", d);
    expectNear(stopped.finalPosition, {0, 0, 0}, 0);
    EXPECT_EQ(stopped.segments.size(), 0u);
    EXPECT_EQ(stopped.endpoints.size(), 0u);
    expectNear(draw("AAAAAAAAAARF", d).finalPosition, {1, 0, 0}, 0);
    EXPECT_EQ(draw(std::string(40, 'O') + "RF", d).finalPosition.x, -1.0); // alpha clamps at 180
}

TEST(lsystem_Turtle, ZeroStopsConnectionOfItsBranchOnly) {
    const Skeleton s = draw("F[0RF]F[LF]");
    ASSERT_EQ(s.endpoints.size(), 1u);
    expectNear(s.endpoints[0].position, {2.707107, 0, -0.707107});
    EXPECT_TRUE(s.branches[1].noConnect);
    EXPECT_FALSE(s.branches[0].noConnect);
    EXPECT_FALSE(s.branches[2].noConnect);
}

TEST(lsystem_Turtle, ZeroIsInheritedByBranchesOpenedAfterIt) {
    const Skeleton s = draw("F0[RF]F");
    EXPECT_EQ(s.endpoints.size(), 0u);
    EXPECT_TRUE(s.branches[1].noConnect);
}

TEST(lsystem_Turtle, ConstrainedBoxCutsTheCrossingSegment) {
    Definition d = thesisDefinition();
    d.constrained = ConstrainedMode{ConstrainedMode::Shape::Box, {-0.5, -0.5, -0.5}, {2.5, 0.5, 0.5}};
    const Skeleton line = draw("FFFF", d);
    EXPECT_EQ(line.segments.size(), 2u);
    ASSERT_EQ(line.endpoints.size(), 1u);
    expectNear(line.endpoints[0].position, {2, 0, 0}, 1e-12);
    EXPECT_TRUE(line.branches[0].cut);

    d.constrained->min.z = -2;
    d.constrained->max.z = 2;
    const Skeleton tree = draw("F[RF][LFFFF]F", d);
    EXPECT_EQ(tree.segments.size(), 5u);
    ASSERT_EQ(tree.endpoints.size(), 3u);
    expectNear(tree.endpoints[0].position, {1.707107, 0, 0.707107});
    expectNear(tree.endpoints[1].position, {2.414214, 0, -1.414214});
    expectNear(tree.endpoints[2].position, {2, 0, 0}, 1e-12);
}

TEST(lsystem_Turtle, ConstrainedCutSkipsNestedBranchesOfTheFrame) {
    Definition d = thesisDefinition();
    d.constrained = ConstrainedMode{ConstrainedMode::Shape::Sphere, {}, {}, {0, 0, 0}, 2.5};
    const Skeleton s = draw("F[FF[RF]F]RF", d);
    // The branch is cut at its second F (to x = 3); its nested [RF] and trailing F are skipped.
    ASSERT_EQ(s.segments.size(), 3u);
    expectNear(s.finalPosition, {1 + std::sqrt(0.5), 0, std::sqrt(0.5)}, 1e-9);
    EXPECT_EQ(s.branches.size(), 2u);
    ASSERT_EQ(s.endpoints.size(), 2u);
    expectNear(s.endpoints[0].position, {2, 0, 0}, 1e-12);
}

TEST(lsystem_Turtle, StartOutsideTheVolumeDrawsNothing) {
    Definition d = thesisDefinition();
    d.constrained = ConstrainedMode{ConstrainedMode::Shape::Box, {1, 1, 1}, {2, 2, 2}};
    const Skeleton s = draw("FFF", d);
    EXPECT_TRUE(s.startOutside);
    EXPECT_TRUE(s.segments.empty());
    EXPECT_TRUE(s.endpoints.empty());
}

TEST(lsystem_Turtle, AngleDeviationStaysWithinItsRangeAndIsReproducible) {
    Definition d = thesisDefinition();
    d.params.angleDeviation = 15;
    d.seed = 11;
    const Skeleton a = draw("RFRFRFRF", d), b = draw("RFRFRFRF", d);
    ASSERT_EQ(a.segments.size(), 4u);
    bool anyOff = false;
    double yaw = 0;
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(a.segments[i].to, b.segments[i].to);
        const glm::dvec3 step = a.segments[i].to - a.segments[i].from;
        const double turned = std::remainder(std::atan2(step.z, step.x) * 180 / std::acos(-1.0) - yaw, 360.0);
        EXPECT_GE(turned, 30 - 1e-9);
        EXPECT_LE(turned, 60 + 1e-9);
        anyOff = anyOff || std::abs(turned - 45) > 1e-6;
        yaw += turned;
    }
    EXPECT_TRUE(anyOff);
}

TEST(lsystem_Turtle, AbopFrameTurnsPitchesAndRolls) {
    Definition d = thesisDefinition();
    d.turtle = TurtleKind::Abop;
    d.params.angle = 90;
    expectNear(interpret(d, "F").finalPosition, {1, 0, 0}, 1e-12);
    // '+' is R_U(delta): H' = H cos - L sin with L = -z, so +90 heads +z.
    expectNear(interpret(d, "+F").finalPosition, {0, 0, 1}, 1e-12);
    expectNear(interpret(d, "-F").finalPosition, {0, 0, -1}, 1e-12);
    // '&' is R_L(delta): H' = H cos + U sin.
    expectNear(interpret(d, "&F").finalPosition, {0, 1, 0}, 1e-12);
    expectNear(interpret(d, "|F").finalPosition, {-1, 0, 0}, 1e-12);
    // Roll 90 then turn: the turn now happens in the x-y plane.
    const glm::dvec3 rolled = interpret(d, "\\+F").finalPosition;
    EXPECT_NEAR(std::abs(rolled.y), 1, 1e-12);
    // f moves without drawing; a bracket restores the whole frame.
    const Skeleton s = interpret(d, "F[+F&F]fF");
    EXPECT_EQ(s.segments.size(), 4u);
    expectNear(s.finalPosition, {3, 0, 0}, 1e-12);
    expectNear(s.segments[3].from, {2, 0, 0}, 1e-12);
}

TEST(lsystem_Turtle, AStrayClosingBracketIsAUserError) {
    EXPECT_THROW(draw("F]F"), UserError);
}

// Arbitrary bytes (unknown symbols, unbalanced brackets) never crash either turtle: a stray ']'
// is a UserError, anything else interprets.
TEST(lsystem_Turtle, ArbitraryStringsInterpretOrFailAsUserErrors) {
    for (TurtleKind kind : {TurtleKind::Thesis, TurtleKind::Abop}) {
        Definition d = thesisDefinition();
        d.turtle = kind;
        d.params.angleDeviation = 10;
        d.params.pitchLimit = 60;
        d.constrained = ConstrainedMode{ConstrainedMode::Shape::Sphere, {}, {}, {0, 0, 0}, 20};
        const std::string alphabet = "FfRLUDOABSZ0[]+-&^\\/|X\n";
        for (uint32_t seed = 0; seed < 500; ++seed) {
            std::string text;
            for (uint32_t i = 0; i < 64; ++i) text += alphabet[uniformIndex({seed, Stream::Mutation, 9, i, 0}, uint32_t(alphabet.size()))];
            try {
                const Skeleton s = interpret(d, text);
                for (const Segment& segment : s.segments) EXPECT_LE(glm::length(segment.to), 20.0 + 1e-9) << text;
            } catch (const UserError&) {
                EXPECT_NE(text.find(']'), std::string::npos) << text;
            }
        }
    }
}

} // namespace
} // namespace voxc::lsystem
