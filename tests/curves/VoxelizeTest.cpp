// Voxelisation (spec A4.3): the separating-axis test against an independent clipping oracle,
// the gathered fields against a one-thread gather written out here, the constraint sets of seed
// and guidance curves, and the box and work limits.
#include "Scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
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

// One thread's gather, cell by cell in triangle order, as spec A3.3 states it: every cell a
// triangle overlaps adds the triangle's values at its closest point. voxelize gathers the box's
// halves on two threads; a cell's sums must come out the same bits.
Constraints gatherOneThread(const std::vector<FeatureCurve>& curves, const Box& box) {
    struct Sums {
        glm::dvec3 normal{0.0};
        double amplitude = 0.0, roughness = 0.0, surface = 0.0;
        uint32_t count = 0, seeds = 0;
        std::map<uint16_t, uint32_t> materials;
    };
    std::map<size_t, Sums> cells;
    for (size_t c = 0; c < curves.size(); ++c)
        for (const RibbonTriangle& tri : ribbonTriangles(sampleCurve(curves[c], Limits{}, "curve"), curves[c].seed)) {
            const std::array<glm::dvec3, 3> p = {tri.v[0].position, tri.v[1].position, tri.v[2].position};
            glm::dvec3 face = glm::cross(p[1] - p[0], p[2] - p[0]);
            if (glm::dot(face, tri.v[0].normal + tri.v[1].normal + tri.v[2].normal) < 0.0) face = -face;
            const glm::dvec3 n = glm::length(face) > 0.0 ? glm::normalize(face)
                                                         : glm::normalize(tri.v[0].normal + tri.v[1].normal + tri.v[2].normal);
            // The cells whose cube meets the triangle's bounds: centre within half a voxel of them.
            glm::ivec3 first, last;
            for (int a = 0; a < 3; ++a) {
                const double lo = std::min({p[0][a], p[1][a], p[2][a]}), hi = std::max({p[0][a], p[1][a], p[2][a]});
                first[a] = int32_t(std::max(0.0, std::ceil(lo - 0.5)));
                last[a] = int32_t(std::min(double(box.size[a] - 1), std::floor(hi + 0.5)));
            }
            for (int32_t z = first.z; z <= last.z; ++z)
                for (int32_t y = first.y; y <= last.y; ++y)
                    for (int32_t x = first.x; x <= last.x; ++x) {
                        const glm::dvec3 centre(x, y, z);
                        if (!triangleOverlapsCube(p, centre, 1.0)) continue;
                        Sums& s = cells[box.index(x, y, z)];
                        const glm::dvec3 w = closestBarycentric(p, centre);
                        s.normal += w[0] * tri.v[0].normal + w[1] * tri.v[1].normal + w[2] * tri.v[2].normal;
                        s.amplitude += w[0] * tri.v[0].amplitude + w[1] * tri.v[1].amplitude + w[2] * tri.v[2].amplitude;
                        s.roughness += w[0] * tri.v[0].roughness + w[1] * tri.v[1].roughness + w[2] * tri.v[2].roughness;
                        ++s.count;
                        ++s.materials[tri.material];
                        if (tri.seed) s.surface += glm::dot(n, centre - p[0]), ++s.seeds;
                    }
        }
    Constraints out(box);
    for (const auto& [i, s] : cells) {
        out.flags[i] = kInParams;
        const double length = glm::length(s.normal);
        if (length >= 1e-6) {
            out.flags[i] |= kInNormals;
            out.normalX.values[i] = float(s.normal.x / length);
            out.normalY.values[i] = float(s.normal.y / length);
            out.normalZ.values[i] = float(s.normal.z / length);
            if (s.seeds > 0) out.flags[i] |= kInSurface, out.surface.values[i] = float(s.surface / s.seeds);
        }
        out.amplitude.values[i] = float(s.amplitude / s.count);
        out.roughness.values[i] = float(s.roughness / s.count);
        uint32_t most = 0;
        for (const auto& [m, n] : s.materials)
            if (n > most) out.material[i] = m, most = n;
    }
    return out;
}

template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(CurvesVoxelize, BothHalvesGatherAsOneThreadWould) {
    // Curves crossing the box's middle slice, so cells on both sides (and their triangles) are
    // shared by the halves; two materials meet on the cliff's face.
    const std::vector<FeatureCurve> scene = test::cliffScene();
    const Box box = test::box643();
    const Constraints got = voxelize(scene, box, SeedValue::PlaneDistance, Limits{});
    const Constraints want = gatherOneThread(scene, box);
    size_t hit = 0;
    for (uint8_t f : want.flags) hit += f != 0;
    EXPECT_GT(hit, 1000u);
    EXPECT_TRUE(sameBits(got.flags, want.flags));
    EXPECT_TRUE(sameBits(got.material, want.material));
    for (const auto& [g, w] : {std::pair{&got.normalX, &want.normalX}, {&got.normalY, &want.normalY},
                               {&got.normalZ, &want.normalZ}, {&got.amplitude, &want.amplitude},
                               {&got.roughness, &want.roughness}, {&got.surface, &want.surface}})
        EXPECT_TRUE(sameBits(g->values, w->values));
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
