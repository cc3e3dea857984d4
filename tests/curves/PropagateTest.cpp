// Surface propagation and material (spec A4.6, A4.9, A4.10): the cave-roof column with both
// rules, the BFS bookkeeping against an independent recomputation, and the material vote.
#include "Scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <deque>

namespace voxc::curves {
namespace {

// Two up-facing seed planes at y = 4.3 and 12.3 across a 3x17x3 box.
Constraints caveRoof() {
    Constraints cs(Box{glm::ivec3(0), glm::ivec3(3, 17, 3)});
    for (int32_t z = 0; z < 3; ++z)
        for (int32_t x = 0; x < 3; ++x)
            for (const auto& [y, plane] : {std::pair{4, 4.3}, std::pair{12, 12.3}}) {
                const size_t i = cs.box.index(x, y, z);
                cs.flags[i] = kInNormals | kInParams | kInSurface;
                cs.normalY.values[i] = 1.0f;
                cs.surface.values[i] = float(double(y) - plane);
            }
    return cs;
}

std::vector<double> crossings(const Field3& f) {
    std::vector<double> out;
    for (int32_t y = 0; y + 1 < f.box.size.y; ++y) {
        const double a = f.at(1, y, 1), b = f.at(1, y + 1, 1);
        if ((a < 0.0) != (b < 0.0)) out.push_back(y + a / (a - b));
    }
    return out;
}

TEST(CurvesPropagate, CaveRoofColumn) {
    const Result r = solveCurves(caveRoof(), Options{}, Limits{});
    const double expected[17] = {-4.3, -3.3, -2.3, -1.3, -0.3, 0.7, 1.7, 2.7, 3.7, -3.3, -2.3, -1.3, -0.3, 0.7, 1.7, 2.7, 3.7};
    for (int32_t y = 0; y < 17; ++y) EXPECT_NEAR(r.surface.distance.at(1, y, 1), expected[y], 1e-5) << y;
    const auto raw = crossings(r.surface.distance), smooth = crossings(r.smoothed);
    ASSERT_EQ(raw.size(), 3u);
    ASSERT_EQ(smooth.size(), 3u);
    EXPECT_NEAR(raw[0], 4.300, 5e-4);
    EXPECT_NEAR(raw[1], 8.529, 5e-4);
    EXPECT_NEAR(raw[2], 12.300, 5e-4);
    EXPECT_NEAR(smooth[0], 4.300, 5e-4);
    EXPECT_NEAR(smooth[1], 8.567, 5e-4);
    EXPECT_NEAR(smooth[2], 12.300, 5e-4);
}

TEST(CurvesPropagate, CaveRoofColumnWithThePrintedSignedMin) {
    Options options;
    options.propagate = PropagateRule::SignedMin;
    const Result r = solveCurves(caveRoof(), options, Limits{});
    EXPECT_NEAR(r.surface.distance.at(1, 8, 1), -4.3, 1e-5);
    const auto raw = crossings(r.surface.distance), smooth = crossings(r.smoothed);
    ASSERT_EQ(raw.size(), 3u);
    ASSERT_EQ(smooth.size(), 3u);
    EXPECT_NEAR(raw[1], 7.386, 5e-4);
    EXPECT_NEAR(smooth[1], 7.233, 5e-4);
}

std::vector<int32_t> bfsDistance(const Box& b, const std::vector<uint8_t>& flags, uint8_t flag) {
    std::vector<int32_t> distance(b.cellCount(), -1);
    std::deque<glm::ivec3> queue;
    for (int32_t z = 0; z < b.size.z; ++z)
        for (int32_t y = 0; y < b.size.y; ++y)
            for (int32_t x = 0; x < b.size.x; ++x)
                if (flags[b.index(x, y, z)] & flag) distance[b.index(x, y, z)] = 0, queue.push_back({x, y, z});
    while (!queue.empty()) {
        const glm::ivec3 p = queue.front();
        queue.pop_front();
        for (const auto& d : kNeighbourOffsets) {
            const glm::ivec3 q = p + glm::ivec3(d[0], d[1], d[2]);
            if (!b.contains(q.x, q.y, q.z) || distance[b.index(q.x, q.y, q.z)] >= 0) continue;
            distance[b.index(q.x, q.y, q.z)] = distance[b.index(p.x, p.y, p.z)] + 1;
            queue.push_back(q);
        }
    }
    return distance;
}

// A4.10: every cell set once, at its BFS distance; the value recomputed independently from the
// neighbours of earlier layers is the stored one, bit for bit. The host values the cells in
// bands of slices (Bfs.h, growLayers): the second box has layers of more than 8,192 cells over
// 160 slices, the third is long and thin (3x8x300), so each band holds groups of slices.
void expectBookkeeping(const Box& box) {
    const Constraints cs = voxelize(test::cliffScene(), box, SeedValue::PlaneDistance, Limits{});
    const Result r = solveCurves(cs, Options{}, Limits{});
    const Box& b = cs.box;
    const std::vector<int32_t> distance = bfsDistance(b, cs.flags, kInSurface);
    std::vector<size_t> layerSizes;
    for (int32_t d : distance)
        if (d >= 0) layerSizes.resize(std::max(layerSizes.size(), size_t(d) + 1)), ++layerSizes[size_t(d)];
    if (box.size.x > 64) {
        EXPECT_GT(*std::max_element(layerSizes.begin(), layerSizes.end()), 8192u);
    }
    int32_t maxDistance = 0;
    for (int32_t z = 0; z < b.size.z; ++z)
        for (int32_t y = 0; y < b.size.y; ++y)
            for (int32_t x = 0; x < b.size.x; ++x) {
                const size_t i = b.index(x, y, z);
                ASSERT_EQ(r.surface.layer[i], distance[i]);
                maxDistance = std::max(maxDistance, distance[i]);
                if (distance[i] <= 0) continue;
                float best = 0.0f;
                bool found = false;
                for (int axis = 0; axis < 3; ++axis)
                    for (int step : {-1, 1}) {
                        glm::ivec3 q(x, y, z);
                        q[axis] += step;
                        if (!b.contains(q.x, q.y, q.z) || distance[b.index(q.x, q.y, q.z)] >= distance[i]) continue;
                        const Field3* n[3] = {&r.normalX, &r.normalY, &r.normalZ};
                        const float half = (n[axis]->values[i] + n[axis]->values[b.index(q.x, q.y, q.z)]) * 0.5f;
                        const float v = r.surface.distance.at(q.x, q.y, q.z) + (step < 0 ? half : -half);
                        if (!found || std::abs(v) < std::abs(best) || (std::abs(v) == std::abs(best) && v < best))
                            best = v, found = true;
                    }
                const float stored = r.surface.distance.values[i];
                ASSERT_EQ(std::memcmp(&best, &stored, sizeof best), 0) << x << "," << y << "," << z;
            }
    EXPECT_EQ(r.surface.layers, maxDistance);
    EXPECT_GT(maxDistance, 8);
}

TEST(CurvesPropagate, BookkeepingMatchesAnIndependentRecomputation) {
    expectBookkeeping(test::box643());
    expectBookkeeping(Box{glm::ivec3(0), glm::ivec3(160, 64, 160)});
    expectBookkeeping(Box{glm::ivec3(20, 10, 0), glm::ivec3(3, 8, 300)});
}

// Slices of more than 2^15 cells: the fronts list their cells in 32 bits (FrontOrder), not 16.
TEST(CurvesPropagate, BookkeepingWithWideSlices) {
    expectBookkeeping(Box{glm::ivec3(0, 0, 8), glm::ivec3(64, 520, 8)});
}

TEST(CurvesPropagate, UnreachableCellsAreAir) {
    Constraints cs(Box{glm::ivec3(0), glm::ivec3(4, 4, 4)});
    const Result r = solveCurves(cs, Options{}, Limits{});
    for (float v : r.smoothed.values) ASSERT_TRUE(v > 0.0f && std::isinf(v));
    for (uint8_t a : r.material.assigned) ASSERT_EQ(a, 0);
}

// A4.9: two ribbons with materials 5 and 9; a cell strictly closer (L1) to one takes its material.
TEST(CurvesMaterial, NearerRibbonWins) {
    const glm::dvec3 up(0.0, 1.0, 0.0), along(1.0, 0.0, 0.0);
    const FeatureCurve low = test::planeCurve({31.7, 6.4, 32.2}, up, along, 60.0, 5);
    const FeatureCurve high = test::planeCurve({31.7, 22.6, 32.2}, up, along, 60.0, 9);
    const Box box = test::box643();
    const Constraints cs = voxelize({low, high}, box, SeedValue::PlaneDistance, Limits{});
    const Result r = solveCurves(cs, Options{}, Limits{});
    const auto dLow = bfsDistance(box, voxelize({low}, box, SeedValue::PlaneDistance, Limits{}).flags, kInParams);
    const auto dHigh = bfsDistance(box, voxelize({high}, box, SeedValue::PlaneDistance, Limits{}).flags, kInParams);
    size_t decided = 0;
    for (size_t i = 0; i < cs.flags.size(); ++i) {
        ASSERT_TRUE(r.material.assigned[i]);
        const float conf = r.material.confidence.values[i];
        ASSERT_TRUE(conf > 0.0f && conf <= 1.0f);
        if (cs.flags[i] & kInParams) {
            ASSERT_EQ(conf, 1.0f);
        }
        if (dLow[i] != dHigh[i]) {
            ASSERT_EQ(r.material.material[i], dLow[i] < dHigh[i] ? 5 : 9) << i;
            ++decided;
        }
    }
    EXPECT_GT(decided, cs.flags.size() / 2);
    EXPECT_GT(r.material.layers, 0);
}

} // namespace
} // namespace voxc::curves
