#include "voxc/builtins/Shapes.h"

#include <algorithm>
#include <set>
#include <cmath>
#include <vector>
#include <gtest/gtest.h>

namespace voxc {
namespace {

Program programWith(StartShape shape) {
    Program program;
    program.start.push_back(shape);
    return program;
}

TEST(builtins_shapes, UniqueNamesAndKeys) {
    std::set<std::string_view> names;
    for (const ShapeInfo& info : shapes()) {
        EXPECT_TRUE(names.insert(info.name).second);
        EXPECT_EQ(findShape(info.name), info.kind);
        std::set<std::string_view> keys;
        for (const KeySpec& key : info.keys) {
            EXPECT_TRUE(keys.insert(key.name).second) << info.name << "." << key.name;
            EXPECT_LE(key.min, key.max);
        }
        EXPECT_FALSE(info.glsl(StartShape{}).empty());
    }
}

TEST(builtins_perlin, PermutationIsPerlinsReferenceTable) {
    const std::span<const int, 256> table = perlinPermutation();
    std::vector<int> sorted(table.begin(), table.end());
    std::sort(sorted.begin(), sorted.end());
    for (int i = 0; i < 256; ++i) EXPECT_EQ(sorted[size_t(i)], i);
    // First and last entries of Ken Perlin's Improved Noise (2002) permutation.
    EXPECT_EQ(table[0], 151);
    EXPECT_EQ(table[1], 160);
    EXPECT_EQ(table[255], 180);
}

TEST(builtins_perlin, ZeroOnTheIntegerLattice) {
    for (int x = -3; x <= 3; ++x)
        for (int y = -3; y <= 3; ++y) EXPECT_EQ(perlin2(float(x), float(y)), 0.0f);
}

TEST(builtins_perlin, BoundedAndContinuous) {
    float previous = perlin2(0.0f, 0.37f);
    for (int i = 1; i < 4000; ++i) {
        const float x = float(i) * 0.01f;
        const float value = perlin2(x, 0.37f);
        EXPECT_LE(std::fabs(value), 1.0f);
        EXPECT_LT(std::fabs(value - previous), 0.05f) << "jump at x=" << x;
        previous = value;
    }
}

TEST(builtins_perlin, NotConstant) {
    float lo = 1.0f, hi = -1.0f;
    for (int i = 0; i < 1000; ++i) {
        const float v = perlin2(float(i) * 0.173f, float(i) * 0.071f);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    EXPECT_LT(lo, -0.3f);
    EXPECT_GT(hi, 0.3f);
}

TEST(builtins_heightfield, SeedChangesTheSurfaceAndParametersMatter) {
    HeightfieldParams params;
    int differentSeed = 0, differentGain = 0;
    HeightfieldParams flatter = params;
    flatter.gain = 0.1f;
    for (int x = 0; x < 64; ++x) {
        differentSeed += heightfieldHeight(params, 1, x, 5) != heightfieldHeight(params, 2, x, 5);
        differentGain += heightfieldHeight(params, 1, x, 5) != heightfieldHeight(flatter, 1, x, 5);
        const float h = heightfieldHeight(params, 1, x, 5);
        EXPECT_LE(std::fabs(h - params.base), params.amplitude * 2.0f);
    }
    EXPECT_GT(differentSeed, 32);
    EXPECT_GT(differentGain, 32);
}

TEST(builtins_shapes, BoxIsHalfOpen) {
    StartShape box;
    box.kind = ShapeKind::Box;
    box.min = {2, 2, 2};
    box.max = {4, 4, 4};
    box.value = 0.75f;
    const Program program = programWith(box);
    EXPECT_EQ(startVoxel(program, {2, 2, 2}).density, 0.75f);
    EXPECT_EQ(startVoxel(program, {3, 3, 3}).density, 0.75f);
    EXPECT_EQ(startVoxel(program, {4, 3, 3}).density, 0.0f);
    EXPECT_EQ(startVoxel(program, {1, 3, 3}).density, 0.0f);
}

TEST(builtins_shapes, SphereIncludesItsRadius) {
    StartShape sphere;
    sphere.kind = ShapeKind::Sphere;
    sphere.center = {10, 10, 10};
    sphere.radius = 3;
    const Program program = programWith(sphere);
    EXPECT_EQ(startVoxel(program, {13, 10, 10}).density, 1.0f);
    EXPECT_EQ(startVoxel(program, {14, 10, 10}).density, 0.0f);
    EXPECT_EQ(startVoxel(program, {12, 12, 11}).density, 1.0f); // 4 + 4 + 1 == 9: on the sphere
    EXPECT_EQ(startVoxel(program, {12, 12, 12}).density, 0.0f); // 4 + 4 + 4 > 9
}

TEST(builtins_shapes, WallAndHalfSpace) {
    StartShape wall;
    wall.kind = ShapeKind::Wall;
    wall.axis = 2;
    wall.at = 5;
    wall.thickness = 2;
    const Program walls = programWith(wall);
    EXPECT_EQ(startVoxel(walls, {0, 0, 4}).density, 0.0f);
    EXPECT_EQ(startVoxel(walls, {0, 0, 5}).density, 1.0f);
    EXPECT_EQ(startVoxel(walls, {0, 0, 6}).density, 1.0f);
    EXPECT_EQ(startVoxel(walls, {0, 0, 7}).density, 0.0f);

    StartShape half;
    half.kind = ShapeKind::HalfSpace;
    half.normal = {0, 1, 0};
    half.offset = 3;
    const Program halves = programWith(half);
    EXPECT_EQ(startVoxel(halves, {9, 3, 9}).density, 1.0f);
    EXPECT_EQ(startVoxel(halves, {9, 4, 9}).density, 0.0f);
}

TEST(builtins_shapes, LaterShapesOverwriteEarlierOnes) {
    Program program;
    StartShape fill;
    fill.kind = ShapeKind::Fill;
    fill.value = 1.0f;
    StartShape hole;
    hole.kind = ShapeKind::Box;
    hole.min = {0, 0, 0};
    hole.max = {1, 1, 1};
    hole.value = 0.0f;
    program.start = {fill, hole};
    EXPECT_EQ(startVoxel(program, {0, 0, 0}).density, 0.0f);
    EXPECT_EQ(startVoxel(program, {1, 0, 0}).density, 1.0f);
}

TEST(builtins_shapes, HeightfieldUsesWorldColumns) {
    StartShape ground;
    ground.kind = ShapeKind::Heightfield;
    Program program = programWith(ground);
    program.world.origin = {1000, 0, -2000};
    const float h = heightfieldHeight(ground.heightfield, program.world.seed, 1003, -1995);
    const int below = int(std::ceil(h)) - 1;
    EXPECT_EQ(startVoxel(program, {3, below, 5}).density, 1.0f);
    EXPECT_EQ(startVoxel(program, {3, below + 1, 5}).density, 0.0f);
}

} // namespace
} // namespace voxc
