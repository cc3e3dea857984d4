// Speleothems on the CPU (lsystem-spec §6.2 and §10 test 17): closed runs only, the taper, kinds,
// hoodoos 2 x 2, materials, protected voxels, determinism and independence of visiting order
// and grid extent.
#include "voxc/generators/WorkErrors.h"
#include "voxc/generators/caves/Speleothems.h"

#include "GridCompare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

namespace voxc::caves {
namespace {

constexpr uint8_t kFlowstone = 7;
constexpr uint8_t kRock = 1;

// Every closed run spawns with reach 1 (spec test 17): the whole cluster range, a threshold
// below every noise value, a growth that saturates phi.
SpeleothemParams alwaysSpawn(SpeleothemKind kind) {
    SpeleothemParams p;
    p.kind = kind;
    p.clusterLow = -1.0f;
    p.clusterHigh = 1.0f;
    p.spawnThreshold = -1.0f;
    p.growth = 1000.0f;
    p.maxGap = 64;
    p.material = kFlowstone;
    return p;
}

// Rock (density 1, material rock) at y <= floorY and y >= ceilingY, air (0) between.
DenseGrid slab(glm::ivec3 size, int32_t floorY, int32_t ceilingY) {
    DenseGrid grid(size);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x)
                if (y <= floorY || y >= ceilingY) grid.at({x, y, z}) = 1.0f, grid.materialAt({x, y, z}) = kRock;
    return grid;
}

// An irregular cave: rock except where a few overlapping spheres and a tunnel carve air.
DenseGrid cave(glm::ivec3 size) {
    DenseGrid grid(size, 1.0f);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const glm::vec3 p(x, y, z);
                const float room = glm::length(p - glm::vec3(12, 20, 14)) - 10.0f;
                const float hall = glm::length(p - glm::vec3(28, 24, 22)) - 13.0f;
                const float tunnel = glm::length(glm::vec2(p.y - 18.0f, p.z - 20.0f)) - 4.0f;
                if (std::min({room, hall, tunnel}) < 0.0f) grid.at({x, y, z}) = 0.0f;
                else grid.materialAt({x, y, z}) = kRock;
            }
    return grid;
}

TEST(caves_Speleothems, ColumnsJoinFloorToCeiling) { // spec test 17
    for (SpeleothemKind kind : {SpeleothemKind::Column, SpeleothemKind::Hoodoo}) {
        DenseGrid grid = slab({20, 52, 18}, 9, 41);
        growSpeleothems(alwaysSpawn(kind), 5, {-13, 3, 29}, grid);
        for (int z = 0; z < 18; ++z)
            for (int x = 0; x < 20; ++x)
                for (int y = 10; y <= 40; ++y) {
                    ASSERT_GE(grid.at({x, y, z}), 0.5f) << speleothemKindName(kind) << " (" << x << "," << y << "," << z << ")";
                    ASSERT_EQ(grid.materialAt({x, y, z}), kFlowstone);
                }
    }
}

TEST(caves_Speleothems, StalactitesAndStalagmitesStopAtTheMidpoint) {
    // gap 31: L = ceil(31 / 2) = 16, so a stalactite covers y 40..25 and a stalagmite 10..25.
    const glm::ivec3 size{6, 52, 5};
    DenseGrid down = slab(size, 9, 41), up = slab(size, 9, 41);
    growSpeleothems(alwaysSpawn(SpeleothemKind::Stalactite), 5, {0, 0, 0}, down);
    growSpeleothems(alwaysSpawn(SpeleothemKind::Stalagmite), 5, {0, 0, 0}, up);
    for (int y = 10; y <= 40; ++y) {
        EXPECT_EQ(down.at({2, y, 3}) >= 0.5f, y >= 25) << y;
        EXPECT_EQ(up.at({2, y, 3}) >= 0.5f, y <= 25) << y;
    }
}

TEST(caves_Speleothems, TaperDensities) {
    // 1 - (k + 1) / (L + 1) of the spec, mapped to [0.5, 1].
    for (int32_t length : {1, 2, 5, 16, 33})
        for (int32_t taper : {0, 1, 2, 5})
            for (int32_t k = 0; k < length; ++k) {
                const double t = 1.0 - double(k + 1) / double(length + 1);
                EXPECT_NEAR(taperDensity(k, length, taper), 0.5 + 0.5 * std::pow(t, taper), 1e-6)
                    << k << " of " << length << " taper " << taper;
                if (k > 0) {
                    EXPECT_LT(taperDensity(k, length, taper), taperDensity(k - 1, length, taper) + (taper == 0));
                }
            }
    EXPECT_EQ(taperDensity(0, 3, 1), 0.875f); // exact: 0.5 + 0.5 * 3/4
    EXPECT_EQ(taperDensity(2, 3, 1), 0.625f);
    EXPECT_EQ(taperDensity(7, 9, 0), 1.0f);   // taper 0: blunt

    // In the grid: gap 7 gives L = 4 from the ceiling at y 8, densities falling to the tip.
    DenseGrid grid = slab({3, 12, 3}, 0, 8);
    growSpeleothems(alwaysSpawn(SpeleothemKind::Stalactite), 1, {0, 0, 0}, grid);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(grid.at({1, 7 - k, 1}), taperDensity(k, 4, 1)) << k;
    for (int y = 1; y <= 3; ++y) EXPECT_EQ(grid.at({1, y, 1}), 0.0f) << y;
}

TEST(caves_Speleothems, OpenRunsNeverSpawn) {
    // A rock slab in mid air: the air below reaches the grid's bottom, the air above its top.
    DenseGrid grid({10, 40, 10});
    for (int z = 0; z < 10; ++z)
        for (int y = 15; y <= 20; ++y)
            for (int x = 0; x < 10; ++x) grid.at({x, y, z}) = 1.0f;
    const DenseGrid before = grid;
    for (SpeleothemKind kind : {SpeleothemKind::Stalactite, SpeleothemKind::Stalagmite, SpeleothemKind::Column,
                                SpeleothemKind::Hoodoo}) {
        growSpeleothems(alwaysSpawn(kind), 3, {0, -20, 0}, grid);
        EXPECT_EQ(test::countVoxelDifferences(before, grid), 0u) << speleothemKindName(kind);
    }
}

TEST(caves_Speleothems, GapsOutsideTheRangeStayAir) {
    SpeleothemParams params = alwaysSpawn(SpeleothemKind::Column);
    params.minGap = 5;
    params.maxGap = 20;
    for (int32_t gap : {2, 4, 21, 30}) {
        DenseGrid grid = slab({4, 40, 4}, 3, 4 + gap);
        const DenseGrid before = grid;
        growSpeleothems(params, 0, {0, 0, 0}, grid);
        EXPECT_EQ(test::countVoxelDifferences(before, grid), 0u) << gap;
    }
    DenseGrid inside = slab({4, 40, 4}, 3, 4 + 5);
    growSpeleothems(params, 0, {0, 0, 0}, inside);
    EXPECT_GE(inside.at({0, 6, 0}), 0.5f);
}

TEST(caves_Speleothems, ClosedRunsAreListedBottomUp) {
    DenseGrid grid = slab({1, 30, 1}, 2, 27);
    grid.at({0, 10, 0}) = 1.0f; // splits the run in two
    grid.at({0, 11, 0}) = 0.7f;
    const std::vector<AirRun> runs = closedRuns(SpeleothemParams{}, AirMask(grid), 0, 0);
    ASSERT_EQ(runs.size(), 2u);
    EXPECT_EQ(runs[0].floorY, 2);
    EXPECT_EQ(runs[0].ceilingY, 10);
    EXPECT_EQ(runs[1].floorY, 11);
    EXPECT_EQ(runs[1].ceilingY, 27);
}

TEST(caves_Speleothems, HoodoosAreTwoByTwo) {
    // Only column (3, 3) has a closed run; every other column is air from bottom to top.
    const glm::ivec3 size{8, 40, 8};
    DenseGrid grid(size);
    for (int y = 0; y < size.y; ++y)
        if (y <= 5 || y >= 30) grid.at({3, y, 3}) = 1.0f;
    for (SpeleothemKind kind : {SpeleothemKind::Column, SpeleothemKind::Hoodoo}) {
        DenseGrid out = grid;
        growSpeleothems(alwaysSpawn(kind), 9, {100, -4, -50}, out);
        for (int z = 0; z < size.z; ++z)
            for (int x = 0; x < size.x; ++x) {
                const bool own = x == 3 && z == 3;
                const bool covered = own || (kind == SpeleothemKind::Hoodoo && (x == 3 || x == 4) && (z == 3 || z == 4));
                for (int y = 6; y <= 29; ++y) // gap 24: both halves of 12 meet
                    EXPECT_EQ(out.at({x, y, z}) >= 0.5f, covered) << speleothemKindName(kind) << " " << x << "," << y << "," << z;
                if (covered && !own) { // the neighbours get the same features: same densities
                    for (int y = 6; y <= 29; ++y) EXPECT_EQ(out.at({x, y, z}), out.at({3, y, 3}));
                }
            }
    }
}

TEST(caves_Speleothems, MaterialOnlyWhereAFeatureWins) {
    DenseGrid grid = cave({40, 40, 36});
    const DenseGrid before = grid;
    SpeleothemParams params = alwaysSpawn(SpeleothemKind::Hoodoo);
    params.growth = 0.6f; // features that do not all meet
    growSpeleothems(params, 11, {0, 0, 0}, grid);
    size_t grown = 0;
    for (int z = 0; z < 36; ++z)
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 40; ++x) {
                const glm::ivec3 p{x, y, z};
                const bool wins = grid.at(p) != before.at(p);
                EXPECT_GE(grid.at(p), before.at(p));
                EXPECT_EQ(grid.materialAt(p), wins ? kFlowstone : before.materialAt(p)) << x << "," << y << "," << z;
                if (wins) {
                    EXPECT_LT(before.at(p), 0.5f); // the cave's rock is 1: only air grows
                }
                grown += wins;
            }
    EXPECT_GT(grown, 100u);
}

TEST(caves_Speleothems, ProtectedVoxelsAreNeverWritten) {
    // A stand-in for an L-system's clearance radius: a cylinder along x through the cave.
    const ProtectedVoxel inTunnel = [](glm::ivec3 world) {
        return glm::length(glm::vec2(float(world.y) - 18.0f, float(world.z) + 3.0f)) <= 4.5f;
    };
    DenseGrid grid = cave({40, 40, 36});
    const DenseGrid before = grid;
    growSpeleothems(alwaysSpawn(SpeleothemKind::Hoodoo), 2, {0, 0, -23}, grid, inTunnel);
    size_t protectedAir = 0, grown = 0;
    for (int z = 0; z < 36; ++z)
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 40; ++x) {
                const glm::ivec3 p{x, y, z};
                if (inTunnel(p + glm::ivec3(0, 0, -23))) {
                    EXPECT_EQ(grid.at(p), before.at(p)) << x << "," << y << "," << z;
                    EXPECT_EQ(grid.materialAt(p), before.materialAt(p));
                    protectedAir += before.at(p) < 0.5f;
                } else {
                    grown += grid.at(p) != before.at(p);
                }
            }
    EXPECT_GT(protectedAir, 100u); // the protected voxels are air a feature would have filled
    EXPECT_GT(grown, 100u);
}

TEST(caves_Speleothems, DeterministicAndSeedDependent) {
    const DenseGrid start = cave({40, 40, 36});
    SpeleothemParams params;
    params.kind = SpeleothemKind::Column;
    params.clusterLow = -1.0f; // the default spawn noise alone, so a few columns grow
    DenseGrid a = start, b = start, c = start;
    growSpeleothems(params, 7, {3, 0, 5}, a);
    growSpeleothems(params, 7, {3, 0, 5}, b);
    growSpeleothems(params, 8, {3, 0, 5}, c);
    EXPECT_EQ(test::countVoxelDifferences(a, b), 0u);
    EXPECT_NE(a.data(), start.data());
    EXPECT_NE(a.data(), c.data());
}

TEST(caves_Speleothems, ColumnOrderDoesNotMatter) {
    // Runs are found in the grid before the stage, so visiting columns in reverse (as a GPU
    // may) writes the same voxels, hoodoos included.
    const DenseGrid start = cave({40, 40, 36});
    SpeleothemParams params = alwaysSpawn(SpeleothemKind::Hoodoo);
    params.growth = 0.8f;
    DenseGrid forward = start, backward = start;
    growSpeleothems(params, 4, {0, 0, 0}, forward);
    const AirMask before(backward);
    for (int z = 35; z >= 0; --z)
        for (int x = 39; x >= 0; --x) growSpeleothemColumn(params, 4, {0, 0, 0}, before, x, z, backward);
    EXPECT_EQ(test::countVoxelDifferences(forward, backward), 0u);
    EXPECT_NE(forward.data(), start.data());
}

TEST(caves_Speleothems, ColumnsDoNotDependOnTheGridExtent) {
    // A column's features come from that column (and its -1 neighbours for hoodoos) in world
    // coordinates: a grid cut out of a larger one, full height, grows the same voxels.
    const glm::ivec3 origin{-16, 2, 40};
    const DenseGrid start = cave({40, 40, 36});
    for (SpeleothemKind kind : {SpeleothemKind::Stalactite, SpeleothemKind::Column, SpeleothemKind::Hoodoo}) {
        SpeleothemParams params = alwaysSpawn(kind);
        params.growth = 0.7f;
        params.spawnThreshold = 0.1f;
        DenseGrid whole = start;
        growSpeleothems(params, 13, origin, whole);
        const glm::ivec3 cut{9, 0, 5};
        DenseGrid part({20, 40, 24});
        for (int z = 0; z < 24; ++z)
            for (int y = 0; y < 40; ++y)
                for (int x = 0; x < 20; ++x) {
                    part.at({x, y, z}) = start.at(cut + glm::ivec3(x, y, z));
                    part.materialAt({x, y, z}) = start.materialAt(cut + glm::ivec3(x, y, z));
                }
        growSpeleothems(params, 13, origin + cut, part);
        // A hoodoo's first row and column lack their -1 neighbours in the part.
        const int skip = kind == SpeleothemKind::Hoodoo ? 1 : 0;
        size_t differences = 0;
        for (int z = skip; z < 24; ++z)
            for (int y = 0; y < 40; ++y)
                for (int x = skip; x < 20; ++x) {
                    const glm::ivec3 p{x, y, z};
                    differences += part.at(p) != whole.at(cut + p) || part.materialAt(p) != whole.materialAt(cut + p);
                }
        EXPECT_EQ(differences, 0u) << speleothemKindName(kind);
    }
}

TEST(caves_Speleothems, ParametersAreChecked) {
    EXPECT_NO_THROW(checkSpeleothemParams(SpeleothemParams{}));
    SpeleothemParams edges; // every range's ends, as floats from the checker
    edges.spawnThreshold = float(0.99);
    edges.clusterFrequency = edges.spawnFrequency = edges.growth = 1000.0f;
    edges.taper = 8;
    edges.minGap = edges.maxGap = 4096;
    EXPECT_NO_THROW(checkSpeleothemParams(edges));
    const auto rejects = [](const char* key, auto change) {
        SpeleothemParams p;
        change(p);
        try {
            checkSpeleothemParams(p);
            ADD_FAILURE() << key << " accepted";
        } catch (const generators::ParameterError& e) {
            EXPECT_EQ(e.parameter, key) << e.what();
        }
    };
    rejects("cluster_frequency", [](SpeleothemParams& p) { p.clusterFrequency = NAN; });
    rejects("cluster_frequency", [](SpeleothemParams& p) { p.clusterFrequency = -0.5f; });
    rejects("cluster_low", [](SpeleothemParams& p) { p.clusterLow = 0.5f, p.clusterHigh = 0.4f; });
    rejects("cluster_high", [](SpeleothemParams& p) { p.clusterHigh = 1.5f; });
    rejects("spawn_frequency", [](SpeleothemParams& p) { p.spawnFrequency = INFINITY; });
    rejects("spawn_threshold", [](SpeleothemParams& p) { p.spawnThreshold = 1.0f; });
    rejects("growth", [](SpeleothemParams& p) { p.growth = -1.0f; });
    rejects("taper", [](SpeleothemParams& p) { p.taper = 9; });
    rejects("min_gap", [](SpeleothemParams& p) { p.minGap = 0; });
    rejects("max_gap", [](SpeleothemParams& p) { p.maxGap = 2; });
    rejects("max_gap", [](SpeleothemParams& p) { p.maxGap = 5000; });
    for (SpeleothemKind kind : {SpeleothemKind::Stalactite, SpeleothemKind::Stalagmite, SpeleothemKind::Column,
                                SpeleothemKind::Hoodoo})
        EXPECT_EQ(findSpeleothemKind(speleothemKindName(kind)), kind);
    EXPECT_EQ(findSpeleothemKind("stalactites"), std::nullopt);
}

} // namespace
} // namespace voxc::caves
