// Becher's g (spec A4.1, A2.1), the clamped B-spline, rotation-minimising bitangents and ribbons
// (A4.2), and the located errors of bad curves.
#include "Scenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace voxc::curves {
namespace {

TEST(CurvesG, ValuesOfTheSpec) {
    EXPECT_EQ(peronaMalikG(0.0f, 0.01f), 1.0f);
    EXPECT_NEAR(peronaMalikG(0.01f, 0.01f), 0.5f, 0.5e-7);
    EXPECT_NEAR(peronaMalikG(0.5f, 0.01f), 1.0 / 2501.0, 1e-7 / 2501.0);
}

// A2.1: a zero-length normal gives x = (1 - 0)/2 = 0.5, so g is 1/2501, not 1 as the paper says.
TEST(CurvesG, ZeroLengthNormalIsNotOne) {
    const float dotWithZeroNormal = 0.0f;
    EXPECT_EQ((1.0f - dotWithZeroNormal) * 0.5f, 0.5f);
    EXPECT_LT(peronaMalikG((1.0f - dotWithZeroNormal) * 0.5f, 0.01f), 4.0e-4f);
}

FeatureCurve wavyCurve() {
    FeatureCurve c;
    c.points = {{0.0, 5.0, 0.0}, {10.0, 9.0, 3.0}, {20.0, 4.0, 12.0}, {30.0, 8.0, 15.0}, {36.0, 6.0, 28.0}, {45.0, 10.0, 30.0}};
    ConstraintPoint a, b, m;
    a.t = 0.0, a.right = glm::dvec3(0.0, 1.0, 2.0), a.left = glm::dvec3(0.0, 2.0, -4.0);
    m.t = 0.35, m.amplitude = 4.0;
    b.t = 1.0, b.right = glm::dvec3(0.0, 0.0, 5.0), b.left = glm::dvec3(1.0, 1.0, -1.0);
    c.constraints = {a, m, b};
    return c;
}

TEST(CurvesSpline, InterpolatesTheEndControlVertices) {
    const FeatureCurve c = wavyCurve();
    EXPECT_LE(glm::length(splinePoint(c.points, 0.0) - c.points.front()), 1e-9);
    EXPECT_LE(glm::length(splinePoint(c.points, 1.0) - c.points.back()), 1e-9);
}

TEST(CurvesSpline, DerivativeMatchesFiniteDifferences) {
    const FeatureCurve c = wavyCurve();
    for (double t : {0.05, 0.3, 0.5, 0.77, 0.95}) {
        const double h = 1e-6;
        const glm::dvec3 numeric = (splinePoint(c.points, t + h) - splinePoint(c.points, t - h)) / (2.0 * h);
        EXPECT_LE(glm::length(numeric - splineDerivative(c.points, t)), 1e-5 * glm::length(numeric)) << t;
    }
}

TEST(CurvesSpline, BitangentsArePerpendicularWithInterpolatedLengths) {
    const FeatureCurve c = wavyCurve();
    const auto samples = sampleCurve(c, Limits{}, "curve");
    ASSERT_GT(samples.size(), 100u);
    for (size_t i = 0; i + 1 < samples.size(); ++i)
        ASSERT_LE(glm::length(samples[i + 1].position - samples[i].position), 0.5);
    for (const SpineSample& s : samples) {
        EXPECT_LE(std::abs(glm::dot(s.left, s.tangent)), 1e-9);
        EXPECT_LE(std::abs(glm::dot(s.right, s.tangent)), 1e-9);
        EXPECT_NEAR(glm::length(s.tangent), 1.0, 1e-12);
    }
    // At the ends the bitangents are the constraints' with the tangent component removed.
    const glm::dvec3 t0 = samples.front().tangent, t1 = samples.back().tangent;
    const glm::dvec3 given0(0.0, 1.0, 2.0), given1(0.0, 0.0, 5.0);
    EXPECT_LE(glm::length(samples.front().right - (given0 - glm::dot(given0, t0) * t0)), 1e-9);
    EXPECT_LE(glm::length(samples.back().right - (given1 - glm::dot(given1, t1) * t1)), 1e-9);
    const double lb = glm::length(samples.back().right);
    // Lengths interpolate linearly in w between the constraint points at t = 0.35 and 1.
    const ConstraintPoint& mid = c.constraints[1];
    for (const SpineSample& s : samples) {
        if (s.t < mid.t) continue;
        const double w = (s.t - mid.t) / (1.0 - mid.t);
        const double lm = glm::length(samples[size_t(std::find_if(samples.begin(), samples.end(),
                                                                 [&](const SpineSample& q) { return q.t == mid.t; }) -
                                                    samples.begin())].right);
        EXPECT_NEAR(glm::length(s.right), (1.0 - w) * lm + w * lb, 1e-9);
        EXPECT_NEAR(s.amplitude, (1.0 - w) * 4.0, 1e-12);
    }
}

TEST(CurvesSpline, StraightCurveWithEqualBitangentsGivesAPlanarRibbon) {
    const glm::dvec3 n = glm::normalize(glm::dvec3(1.0, 2.0, 0.5));
    const glm::dvec3 tangent = glm::normalize(glm::cross(n, glm::dvec3(0.0, 0.0, 1.0)));
    const glm::dvec3 q(32.0, 15.6, 32.0);
    const auto triangles = ribbonTriangles(sampleCurve(test::planeCurve(q, n, tangent, 20.0), Limits{}, "curve"), true);
    ASSERT_FALSE(triangles.empty());
    for (const RibbonTriangle& t : triangles)
        for (const RibbonVertex& v : t.v) {
            EXPECT_LE(std::abs(glm::dot(n, v.position - q)), 1e-9);
            EXPECT_LE(glm::length(v.normal - n), 1e-9);
        }
}

TEST(CurvesSpline, DefaultRibbonIsFlatWithNormalUp) {
    FeatureCurve c;
    c.points = {{0.0, 5.0, 0.0}, {4.0, 5.0, 1.0}, {8.0, 5.0, -1.0}, {12.0, 5.0, 0.0}};
    c.constraints = {ConstraintPoint{}, ConstraintPoint{}};
    c.constraints[1].t = 1.0;
    for (const RibbonTriangle& t : ribbonTriangles(sampleCurve(c, Limits{}, "curve"), true))
        for (const RibbonVertex& v : t.v) {
            EXPECT_NEAR(v.position.y, 5.0, 1e-9);
            EXPECT_LE(glm::length(v.normal - glm::dvec3(0.0, 1.0, 0.0)), 1e-9);
        }
}

template <typename Error>
Error thrown(const FeatureCurve& c) {
    try {
        sampleCurve(c, Limits{}, "curve 0");
    } catch (const Error& e) {
        return e;
    }
    ADD_FAILURE() << "no error";
    return Error("", 0.0, "");
}

TEST(CurvesErrors, ConstraintOrderAndRange) {
    FeatureCurve c = wavyCurve();
    c.constraints[1].t = 1.0;
    EXPECT_EQ(thrown<ParameterError>(c).parameter, "curve 0 constraint 2 t");
    c = wavyCurve();
    c.constraints[0].t = 0.1;
    EXPECT_EQ(thrown<ParameterError>(c).value, 0.1);
    c = wavyCurve();
    c.constraints[1].roughness = 1.5;
    EXPECT_EQ(thrown<ParameterError>(c).parameter, "curve 0 constraint 1 roughness");
    c = wavyCurve();
    c.points[2].x = NAN;
    EXPECT_EQ(thrown<ParameterError>(c).parameter, "curve 0 point 2[0]");
    c = wavyCurve();
    c.points.resize(3);
    EXPECT_EQ(thrown<ParameterError>(c).value, 3.0);
}

TEST(CurvesErrors, DegenerateBitangents) {
    FeatureCurve c = wavyCurve();
    const glm::dvec3 tangent = glm::normalize(splineDerivative(c.points, 0.0));
    c.constraints[0].left = 4.0 * tangent; // along the curve: nothing perpendicular is left
    EXPECT_EQ(thrown<ParameterError>(c).parameter, "curve 0 constraint 0 left");
    FeatureCurve vertical;
    vertical.points = {{0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 2.0, 0.0}, {0.0, 3.0, 0.0}};
    vertical.constraints = {ConstraintPoint{}, ConstraintPoint{}};
    vertical.constraints[1].t = 1.0;
    EXPECT_EQ(thrown<ParameterError>(vertical).parameter, "curve 0 constraint 0 left (default)");
    FeatureCurve opposite = wavyCurve();
    opposite.constraints.erase(opposite.constraints.begin() + 1);
    opposite.points = {{0.0, 0.0, 0.0}, {5.0, 0.0, 0.0}, {10.0, 0.0, 0.0}, {15.0, 0.0, 0.0}};
    opposite.constraints[0].right = glm::dvec3(0.0, 0.0, 2.0);
    opposite.constraints[1].right = glm::dvec3(0.0, 0.0, -2.0);
    EXPECT_EQ(thrown<ParameterError>(opposite).requirement, "the bitangents of two constraint points cancel (opposite directions)");
}

TEST(CurvesErrors, SegmentLimitCarriesTheNumbers) {
    FeatureCurve c = wavyCurve();
    Limits limits;
    limits.maxSegmentsPerCurve = 100;
    try {
        sampleCurve(c, limits, "curve 0");
        FAIL() << "no error";
    } catch (const LimitError& e) {
        EXPECT_EQ(e.limit, 100u);
        EXPECT_EQ(e.value, 192u); // 8 * 6 doubled twice: the first count over 100
    }
}

} // namespace
} // namespace voxc::curves
