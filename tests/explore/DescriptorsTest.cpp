// The descriptors' definitions on hand-made grids (docs/explore.md).
#include "voxc/explore/Descriptors.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace voxc;
using namespace voxc::explore;

namespace {

DenseGrid boxGrid(glm::ivec3 size, glm::ivec3 lo, glm::ivec3 hi, float inside = 1.0f) {
    DenseGrid grid(size, 0.0f);
    for (int z = lo.z; z < hi.z; ++z)
        for (int y = lo.y; y < hi.y; ++y)
            for (int x = lo.x; x < hi.x; ++x) grid.at({x, y, z}) = inside;
    return grid;
}

} // namespace

TEST(Descriptors, SolidFractionCountsVoxelsAtOrAboveIso) {
    DenseGrid grid({4, 4, 4}, 0.0f);
    grid.at({0, 0, 0}) = 0.5f;   // exactly iso: solid
    grid.at({1, 0, 0}) = 0.49f;  // below: air
    grid.at({2, 0, 0}) = 1.0f;
    EXPECT_DOUBLE_EQ(describeVolume(grid, 0.5f).solidFraction, 2.0 / 64.0);
    EXPECT_DOUBLE_EQ(describeVolume(grid, 0.4f).solidFraction, 3.0 / 64.0);
    EXPECT_DOUBLE_EQ(describeVolume(DenseGrid({3, 3, 3}, 1.0f), 0.5f).solidFraction, 1.0);
}

TEST(Descriptors, SurfaceAreaOfABoxIsItsFaceCount) {
    // A 2x3x4 box inside an 8^3 grid: 2*(2*3 + 3*4 + 2*4) = 52 faces.
    EXPECT_DOUBLE_EQ(describeVolume(boxGrid({8, 8, 8}, {1, 2, 3}, {3, 5, 7}), 0.5f).surfaceArea, 52.0);
    // A single voxel has 6 faces; an empty grid none.
    EXPECT_DOUBLE_EQ(describeVolume(boxGrid({8, 8, 8}, {4, 4, 4}, {5, 5, 5}), 0.5f).surfaceArea, 6.0);
    EXPECT_DOUBLE_EQ(describeVolume(DenseGrid({8, 8, 8}, 0.0f), 0.5f).surfaceArea, 0.0);
}

TEST(Descriptors, SurfaceAreaCountsTheGridBorderAsAir) {
    // A full 3x4x5 grid: the whole boundary of the grid, 2*(12 + 20 + 15) = 94.
    EXPECT_DOUBLE_EQ(describeVolume(DenseGrid({3, 4, 5}, 1.0f), 0.5f).surfaceArea, 94.0);
    // A box touching the border at x = 0 still counts those faces.
    EXPECT_DOUBLE_EQ(describeVolume(boxGrid({4, 4, 4}, {0, 0, 0}, {1, 1, 1}), 0.5f).surfaceArea, 6.0);
}

TEST(Descriptors, IouOfIdenticalDisjointAndHalfOverlappingSets) {
    const glm::ivec3 size{10, 4, 4};
    const SolidSet a = solidSet(boxGrid(size, {0, 0, 0}, {4, 4, 4}), 0.5f);
    const SolidSet disjoint = solidSet(boxGrid(size, {6, 0, 0}, {10, 4, 4}), 0.5f);
    const SolidSet shifted = solidSet(boxGrid(size, {2, 0, 0}, {6, 4, 4}), 0.5f); // overlap 2 of 4 columns
    const SolidSet empty = solidSet(DenseGrid(size, 0.0f), 0.5f);
    EXPECT_EQ(a.count, 64u);
    EXPECT_DOUBLE_EQ(intersectionOverUnion(a, a), 1.0);
    EXPECT_DOUBLE_EQ(intersectionOverUnion(a, disjoint), 0.0);
    EXPECT_DOUBLE_EQ(intersectionOverUnion(a, shifted), 32.0 / 96.0);
    EXPECT_DOUBLE_EQ(intersectionOverUnion(empty, empty), 1.0);
    EXPECT_DOUBLE_EQ(intersectionOverUnion(a, empty), 0.0);
}

TEST(Descriptors, PairwiseIouAveragesEveryPair) {
    const glm::ivec3 size{10, 4, 4};
    const SolidSet a = solidSet(boxGrid(size, {0, 0, 0}, {4, 4, 4}), 0.5f);
    const SolidSet b = solidSet(boxGrid(size, {6, 0, 0}, {10, 4, 4}), 0.5f);
    EXPECT_FALSE(pairwiseIou({a}).has_value());
    const auto same = pairwiseIou({a, a, a});
    ASSERT_TRUE(same.has_value());
    EXPECT_DOUBLE_EQ(same->mean, 1.0);
    EXPECT_DOUBLE_EQ(same->stddev, 0.0);
    const auto mixed = pairwiseIou({a, a, b}); // pairs: 1, 0, 0
    ASSERT_TRUE(mixed.has_value());
    EXPECT_DOUBLE_EQ(mixed->mean, 1.0 / 3.0);
    EXPECT_NEAR(mixed->stddev, std::sqrt(1.0 / 3.0), 1e-12);
}

TEST(Descriptors, MeanAndSampleStandardDeviation) {
    const MeanDeviation md = meanDeviation({2, 4, 4, 4, 5, 5, 7, 9});
    EXPECT_DOUBLE_EQ(md.mean, 5.0);
    EXPECT_DOUBLE_EQ(md.stddev, std::sqrt(32.0 / 7.0));
    EXPECT_DOUBLE_EQ(meanDeviation({3.0}).stddev, 0.0);
}
