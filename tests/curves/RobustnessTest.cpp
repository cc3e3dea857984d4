// Hardening: values at the edges of every documented range give finite fields, never NaN; work
// over a limit is refused with the numbers before it runs long.
#include "Scenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace voxc::curves {
namespace {

void expectNoNaN(const Result& r) {
    for (const Field3* f : {&r.normalX, &r.normalY, &r.normalZ, &r.amplitude, &r.roughness})
        for (float v : f->values) ASSERT_TRUE(std::isfinite(v));
    for (const Field3* f : {&r.surface.distance, &r.smoothed})
        for (float v : f->values) ASSERT_FALSE(std::isnan(v)); // +inf is air where no path reaches
}

// The widest ribbons and largest amplitudes the ranges allow, around a curve through the box.
TEST(CurvesRobustness, ExtremeValidValuesStayFinite) {
    FeatureCurve c;
    c.points = {{-40.0, 10.0, 8.0}, {10.0, 30.0, 8.0}, {30.0, -5.0, 8.0}, {80.0, 12.0, 8.0}};
    ConstraintPoint a, b;
    a.t = 0.0, a.amplitude = 16.0, a.roughness = 0.0, a.material = 65535, a.right = glm::dvec3(0.0, 0.0, 1e3);
    b.t = 1.0, b.amplitude = 0.0, b.roughness = 1.0, b.left = glm::dvec3(0.0, 1.0, -0.5);
    c.constraints = {a, b};
    const Box box{glm::ivec3(-1'000'000, -3, -1'000'000) + glm::ivec3(1'000'000 - 8, 0, 1'000'000 - 8),
                  glm::ivec3(40, 24, 24)};
    for (NormalMode mode : {NormalMode::Laplace, NormalMode::PeronaMalik}) {
        Options options;
        options.normals = mode;
        options.smoothPasses = 4;
        const Result r = runCurves({c}, box, options, Limits{});
        expectNoNaN(r);
        for (float v : r.amplitude.values) ASSERT_LE(v, 16.0f + 1e-3f);
    }
}

// A box far from the origin: the solve box is its own grid, so only relative positions matter.
TEST(CurvesRobustness, FarOriginGivesTheSameFields) {
    const Box box = test::box643();
    const glm::ivec3 shift(-999'936, 1'000, 999'872);
    auto scene = test::cliffScene();
    const Result near = runCurves(scene, box, Options{}, Limits{});
    for (auto& c : scene)
        for (auto& p : c.points) p += glm::dvec3(shift);
    const Result far = runCurves(scene, Box{box.min + shift, box.size}, Options{}, Limits{});
    EXPECT_EQ(near.surface.distance.values, far.surface.distance.values);
    EXPECT_EQ(near.material.material, far.material.material);
}

TEST(CurvesRobustness, SegmentBudgetOverAllCurves) {
    Limits limits;
    limits.maxSegments = 1000;
    const auto scene = test::cliffScene();
    try {
        voxelize({scene[0], scene[0], scene[0], scene[0], scene[0]}, test::box643(), SeedValue::PlaneDistance, limits);
        FAIL();
    } catch (const LimitError& e) {
        EXPECT_EQ(e.quantity, "segments over all curves");
        EXPECT_GT(e.value, 1000u);
        EXPECT_EQ(e.limit, 1000u);
    }
}

TEST(CurvesRobustness, HitCellBudget) {
    Limits limits;
    limits.maxConstrainedCells = 100;
    EXPECT_THROW(voxelize(test::cliffScene(), test::box643(), SeedValue::PlaneDistance, limits), LimitError);
}

TEST(CurvesRobustness, CoincidentControlVerticesHaveNoTangent) {
    FeatureCurve c;
    c.points = {{5.0, 5.0, 5.0}, {5.0, 5.0, 5.0}, {5.0, 5.0, 5.0}, {5.0, 5.0, 5.0}};
    c.constraints = {ConstraintPoint{}, ConstraintPoint{}};
    c.constraints[1].t = 1.0;
    EXPECT_THROW(voxelize({c}, test::box643(), SeedValue::PlaneDistance, Limits{}), ParameterError);
}

TEST(CurvesRobustness, CoordinatesBeyondTheRangeAreRefused) {
    FeatureCurve c = test::cliffScene()[0];
    c.points[1].y = 2e6;
    EXPECT_THROW(voxelize({c}, test::box643(), SeedValue::PlaneDistance, Limits{}), ParameterError);
    c = test::cliffScene()[0];
    c.constraints[1].right = glm::dvec3(0.0, INFINITY, 0.0);
    EXPECT_THROW(voxelize({c}, test::box643(), SeedValue::PlaneDistance, Limits{}), ParameterError);
    EXPECT_THROW(voxelize({}, Box{glm::ivec3(0, 0, 2'000'000), glm::ivec3(4)}, SeedValue::PlaneDistance, Limits{}),
                 ParameterError);
}

} // namespace
} // namespace voxc::curves
