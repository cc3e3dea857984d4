// Voxelisation (spec A4.3): the separating-axis test against an independent clipping oracle,
// the constraint sets of seed and guidance curves, and the box and work limits.
#include "Scenes.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

namespace voxc::curves {
namespace {

// Oracle: clip the triangle against the cube's six slabs (Sutherland-Hodgman); any polygon left overlaps.
bool clippedPolygonNonEmpty(std::vector<glm::dvec3> polygon, const glm::dvec3& centre, double half) {
    for (int axis = 0; axis < 3; ++axis)
        for (double side : {-1.0, 1.0}) {
            auto inside = [&](const glm::dvec3& p) { return side * (p[axis] - centre[axis]) <= half; };
            std::vector<glm::dvec3> out;
            for (size_t i = 0; i < polygon.size(); ++i) {
                const glm::dvec3& a = polygon[i];
                const glm::dvec3& b = polygon[(i + 1) % polygon.size()];
                if (inside(a)) out.push_back(a);
                if (inside(a) != inside(b)) {
                    const double plane = centre[axis] + side * half;
                    out.push_back(a + (plane - a[axis]) / (b[axis] - a[axis]) * (b - a));
                }
            }
            polygon = std::move(out);
            if (polygon.empty()) return false;
        }
    return true;
}

TEST(CurvesVoxelize, OverlapMatchesClippingOracleOnRandomTriangles) {
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> coord(-1.0, 7.0);
    size_t hits = 0;
    for (int trial = 0; trial < 1000; ++trial) {
        const std::array<glm::dvec3, 3> tri = {glm::dvec3(coord(rng), coord(rng), coord(rng)),
                                               glm::dvec3(coord(rng), coord(rng), coord(rng)),
                                               glm::dvec3(coord(rng), coord(rng), coord(rng))};
        for (int z = 0; z < 6; ++z)
            for (int y = 0; y < 6; ++y)
                for (int x = 0; x < 6; ++x) {
                    const glm::dvec3 c(x, y, z);
                    const bool oracle = clippedPolygonNonEmpty({tri[0], tri[1], tri[2]}, c, 0.5);
                    ASSERT_EQ(triangleOverlapsCube(tri, c, 1.0), oracle) << trial << " at " << x << "," << y << "," << z;
                    hits += oracle;
                }
    }
    EXPECT_GT(hits, 10000u); // the sample exercises both outcomes
}

TEST(CurvesVoxelize, ClosestPointBarycentrics) {
    const std::array<glm::dvec3, 3> tri = {glm::dvec3(0, 0, 0), glm::dvec3(4, 0, 0), glm::dvec3(0, 4, 0)};
    EXPECT_EQ(closestBarycentric(tri, {1.0, 1.0, 3.0}), glm::dvec3(0.5, 0.25, 0.25));
    EXPECT_EQ(closestBarycentric(tri, {6.0, -1.0, 0.0}), glm::dvec3(0.0, 1.0, 0.0));
    EXPECT_EQ(closestBarycentric(tri, {2.0, -3.0, 1.0}), glm::dvec3(0.5, 0.5, 0.0));
}

TEST(CurvesVoxelize, SeedAndGuidanceSets) {
    const auto scene = test::cliffScene();
    const Constraints both = voxelize(scene, test::box643(), SeedValue::PlaneDistance, Limits{});
    const Constraints guideOnly = voxelize({scene[1]}, test::box643(), SeedValue::PlaneDistance, Limits{});
    size_t surface = 0, guide = 0;
    for (size_t i = 0; i < both.flags.size(); ++i) {
        if (both.flags[i] & kInSurface) {
            ++surface;
            EXPECT_TRUE(both.flags[i] & kInNormals); // Omega_S within Omega_N
            EXPECT_LE(std::abs(both.surface.values[i]), 0.8661f); // a seed cell is cut by its plane
        }
        if (both.flags[i] & kInNormals) {
            EXPECT_TRUE(both.flags[i] & kInParams);
        }
        EXPECT_FALSE(guideOnly.flags[i] & kInSurface);
        if (guideOnly.flags[i]) {
            ++guide;
            EXPECT_TRUE(both.flags[i] & kInParams);
            EXPECT_EQ(guideOnly.material[i], 4);
        }
    }
    EXPECT_GT(surface, 500u);
    EXPECT_GT(guide, 200u);
}

TEST(CurvesVoxelize, ZeroSeedValueOption) {
    const Constraints c = voxelize(test::cliffScene(), test::box643(), SeedValue::Zero, Limits{});
    for (size_t i = 0; i < c.flags.size(); ++i)
        if (c.flags[i] & kInSurface) {
            ASSERT_EQ(c.surface.values[i], 0.0f);
        }
}

TEST(CurvesVoxelize, LimitsCarryTheNumbers) {
    Limits limits;
    try {
        voxelize({}, Box{glm::ivec3(0), glm::ivec3(300, 300, 300)}, SeedValue::PlaneDistance, limits);
        FAIL();
    } catch (const LimitError& e) {
        EXPECT_EQ(e.value, 27'000'000u);
        EXPECT_EQ(e.limit, limits.maxBoxCells);
    }
    limits.maxCellTests = 1000;
    try {
        voxelize(test::cliffScene(), test::box643(), SeedValue::PlaneDistance, limits);
        FAIL();
    } catch (const LimitError& e) {
        EXPECT_EQ(e.quantity, "triangle/cell overlap tests");
        EXPECT_GT(e.value, 1000u);
    }
    EXPECT_THROW(voxelize({}, Box{glm::ivec3(0), glm::ivec3(0, 4, 4)}, SeedValue::PlaneDistance, Limits{}), ParameterError);
}

TEST(CurvesVoxelize, TrianglesOutsideTheBoxCostNothing) {
    Limits limits;
    limits.maxCellTests = 0;
    std::vector<FeatureCurve> far = test::cliffScene();
    for (auto& c : far)
        for (auto& p : c.points) p += glm::dvec3(5000.0, 0.0, 0.0);
    const Constraints c = voxelize(far, test::box643(), SeedValue::PlaneDistance, limits);
    for (uint8_t f : c.flags) ASSERT_EQ(f, 0);
}

} // namespace
} // namespace voxc::curves
