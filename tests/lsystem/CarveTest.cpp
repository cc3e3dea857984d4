// The cave carve's CPU side (docs/architecture.md "Carving"): structural points, displacement,
// binning, and the field through the interpreter's evaluator: spec §10 tests 14 (clearance) and
// 15 (bounded carving) on random grammars and noise settings.
#include "TestDefinitions.h"

#include "voxc/generators/lsystem/Carve.h"
#include "voxc/generators/lsystem/Connect.h"
#include "voxc/generators/lsystem/Expand.h"
#include "voxc/generators/lsystem/RuleFile.h"
#include "voxc/interp/FieldEval.h"
#include "voxc/program/Random.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>

namespace voxc::lsystem {
namespace {

double segmentDistance(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b) {
    const glm::dvec3 d = b - a;
    const double len2 = glm::dot(d, d);
    const double t = len2 > 0 ? std::clamp(glm::dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * d));
}

double skeletonDistance(const Skeleton& skeleton, glm::dvec3 p) {
    double best = INFINITY;
    for (const Segment& s : skeleton.segments) best = std::min(best, segmentDistance(p, s.from, s.to));
    for (const Connection& line : skeleton.connections)
        for (size_t k = 0; k + 1 < line.points.size(); ++k)
            best = std::min(best, segmentDistance(p, line.points[k], line.points[k + 1]));
    return best;
}

double uniformIn(uint32_t seed, uint32_t stream, double lo, double hi) {
    return lo + (hi - lo) * double(mix32(seed * 7919u + stream) >> 8) / double(1u << 24);
}

// The default rule file grown from `seed` with a random angle deviation and step, connected.
Skeleton randomSkeleton(uint32_t seed) {
    Diagnostics diagnostics;
    const auto rules = parseRuleFile(SourceFile("default.rules", std::string(defaultRuleFileText())), diagnostics);
    EXPECT_TRUE(rules.has_value());
    Definition d;
    d.productions = rules->productions;
    d.macros = rules->macros;
    d.seed = seed;
    d.expansions = 2;
    d.params.step = uniformIn(seed, 1, 2, 6);
    d.params.angleDeviation = uniformIn(seed, 2, 0, 30);
    d.params.pitchLimit = 30;
    d.params.start = {40, 24, 40};
    const Expansion e = expand(d);
    Skeleton skeleton = interpret(d, e.symbols, e.types);
    ConnectParams connect;
    connect.chance = 1;
    connect.maxDistance = 30;
    connectBranches(skeleton, connect, seed, d.limits);
    return skeleton;
}

CarveParams randomParams(uint32_t seed) {
    CarveParams p;
    p.radius = uniformIn(seed, 10, 1, 8);
    p.roomRadius = seed % 2 ? uniformIn(seed, 20, 1, 12) : 0;
    p.clearance = uniformIn(seed, 11, 0.5, 3);
    p.curlAmplitude = uniformIn(seed, 12, 0, 8);
    p.yLimit = uniformIn(seed, 13, 0, 1);
    p.simplexAmplitude = uniformIn(seed, 14, 0, 4);
    p.voronoiAmplitude = uniformIn(seed, 15, 0, 4);
    p.minScale = uniformIn(seed, 16, 0.2, 2);
    p.maxScale = p.minScale + uniformIn(seed, 17, 0, 8);
    p.simplexFrequency = uniformIn(seed, 18, 0.01, 0.5);
    p.voronoiFrequency = uniformIn(seed, 19, 0.01, 0.5);
    return p;
}

constexpr glm::ivec3 kOrigin{0, 0, 0}, kSize{80, 48, 80};

TEST(CarveTest, StructuralPointsFollowSpacingAndAddLeaves) {
    Skeleton skeleton;
    skeleton.segments.push_back({{0, 0, 0}, {10, 0, 0}, 0, SymbolType::None, 6});
    skeleton.segments.push_back({{10, 0, 0}, {10, 4, 0}, 0, SymbolType::None, 6});
    skeleton.segments.back().type = SymbolType::Room;
    CarveParams params;
    params.spacing = 4;
    params.roomRadius = 9;
    const std::vector<StructuralPoint> points = structuralPoints(skeleton, params, {});
    // Segment 1: n = 3 (0, 10/3, 20/3); segment 2: n = 1 (its start) and its end, a leaf.
    ASSERT_EQ(points.size(), 5u);
    test::expectNear(points[1].position, {10.0 / 3.0, 0, 0}, 1e-12);
    test::expectNear(points[3].position, {10, 0, 0}, 1e-12);
    test::expectNear(points[4].position, {10, 4, 0}, 1e-12);
    EXPECT_EQ(points[0].radius, params.radius);
    EXPECT_EQ(points[4].radius, 9.0); // the room's
    // Without a spacing, each segment's points are its own radius apart.
    params.spacing = 0;
    params.radius = 5;
    EXPECT_EQ(structuralPoints(skeleton, params, {}).size(), 2u + 1u + 1u);
}

// Without noise (M = 1) a room's centres make air out to room_radius, a tunnel's to radius.
TEST(CarveTest, RoomsTakeTheirOwnRadius) {
    Skeleton skeleton;
    skeleton.segments.push_back({{20, 20, 20}, {21, 20, 20}, 0, SymbolType::Room, 6});
    CarveParams params;
    params.radius = 2;
    params.curlAmplitude = params.simplexAmplitude = params.voronoiAmplitude = 0;
    params.clearance = 0.5;
    const auto carve = [&](double roomRadius, glm::ivec3 voxel) { // f: 1 air, 0 rock
        params.roomRadius = roomRadius;
        const auto set = carvePointSet(skeleton, params, 1, {0, 0, 0}, {48, 48, 48}, {});
        const Field field = carveField(set, params, 1);
        return FieldEvaluator(field, {0, 0, 0}).density(voxel);
    };
    EXPECT_GT(carve(6, {20, 25, 20}), 0.5f); // 5 voxels above the room's first centre
    EXPECT_LT(carve(0, {20, 25, 20}), 0.5f);
    EXPECT_GT(carve(0, {20, 21, 20}), 0.5f);
}

TEST(CarveTest, DisplacementStaysWithinAmplitudeAndYLimit) {
    CarveParams params;
    params.curlAmplitude = 5;
    params.yLimit = 0.25;
    for (uint32_t i = 0; i < 200; ++i) {
        const glm::dvec3 p(uniformIn(i, 1, -500, 500), uniformIn(i, 2, -500, 500), uniformIn(i, 3, -500, 500));
        const glm::dvec3 moved = displacedCentre(p, params, 7);
        EXPECT_LE(glm::length(moved - p), params.curlAmplitude + 1e-9);
        EXPECT_LE(std::fabs(moved.y - p.y), params.yLimit * params.curlAmplitude + 1e-9);
    }
    // A zero amplitude leaves the points where they are.
    params.curlAmplitude = 0;
    test::expectNear(displacedCentre({3, 4, 5}, params, 7), {3, 4, 5}, 0);
}

// Spec test 14: every voxel within r_clear - 1e-4 of the skeleton (connections included) is air.
TEST(CarveTest, ClearanceHoldsForRandomGrammarsAndNoise) {
    for (uint32_t seed = 1; seed <= 12; ++seed) {
        const Skeleton skeleton = randomSkeleton(seed);
        ASSERT_FALSE(skeleton.segments.empty());
        const CarveParams params = randomParams(seed);
        const auto set = carvePointSet(skeleton, params, seed, kOrigin, kSize, {});
        const Field field = carveField(set, params, seed);
        FieldEvaluator evaluator(field, kOrigin);
        int checked = 0;
        for (int z = 0; z < kSize.z; ++z)
            for (int y = 0; y < kSize.y; ++y)
                for (int x = 0; x < kSize.x; ++x) {
                    if (skeletonDistance(skeleton, glm::dvec3(x, y, z)) >= params.clearance - 1e-4) continue;
                    ++checked;
                    ASSERT_TRUE(pointSetClearance(*set, glm::vec3(x, y, z)));
                    const float f = evaluator.density({x, y, z});
                    // subtract: d = min(d, 1 - f) < 0.5 for any d
                    ASSERT_LT(1.0f - f, 0.5f) << "seed " << seed << " at " << x << "," << y << "," << z;
                }
        EXPECT_GT(checked, 0) << "seed " << seed;
    }
}

// Spec test 15: farther than 2R/m_min + 1 from every displaced centre and 1.125 r_clear from the
// skeleton (voxc's clearance falloff), the field is exactly 0, so a subtract keeps the density.
TEST(CarveTest, CarvingIsBoundedBySupport) {
    for (uint32_t seed = 1; seed <= 12; ++seed) {
        const Skeleton skeleton = randomSkeleton(seed);
        const CarveParams params = randomParams(seed);
        const auto set = carvePointSet(skeleton, params, seed, kOrigin, kSize, {});
        const Field field = carveField(set, params, seed);
        FieldEvaluator evaluator(field, kOrigin);

        int outside = 0;
        for (int z = 0; z < kSize.z; z += 2)
            for (int y = 0; y < kSize.y; y += 2)
                for (int x = 0; x < kSize.x; x += 2) {
                    const glm::dvec3 p(x, y, z);
                    if (skeletonDistance(skeleton, p) <= 1.125 * params.clearance) continue;
                    bool near = false;
                    for (size_t i = 0; i < set->centres.size(); ++i) // within 2R_i/m_min + 1
                        near = near || glm::length(p - glm::dvec3(set->centres[i])) <=
                                           2 / (params.minScale * set->centreScales[i]) + 1;
                    if (near) continue;
                    ++outside;
                    ASSERT_EQ(std::bit_cast<uint32_t>(evaluator.density({x, y, z})), 0u)
                        << "seed " << seed << " at " << x << "," << y << "," << z;
                }
        EXPECT_GT(outside, 0) << "seed " << seed;
    }
}

// The lists and their early exit only decide which points are looked at: any cell size, or one
// cell holding every point, gives the floats of a loop over every point.
TEST(CarveTest, DistancesDoNotDependOnTheBinning) {
    const Skeleton skeleton = randomSkeleton(3);
    const CarveParams params;
    const glm::ivec3 origin{-13, 5, 7}; // an odd origin: cells straddle the grid's edges
    const auto set = carvePointSet(skeleton, params, 3, origin, kSize, {});
    const auto everyPoint = [&](glm::vec3 p) {
        float centre = FLT_MAX, segment = FLT_MAX;
        for (size_t i = 0; i < set->centres.size(); ++i)
            centre = std::min(centre, centreDistanceSquared(p, set->centres[i], set->centreScales[i]));
        for (const PointSetSegment& s : set->segments) segment = std::min(segment, segmentDistanceSquared(p, s));
        return glm::vec2(std::min(std::sqrt(centre), set->centreReach), std::min(std::sqrt(segment), set->segmentReach));
    };
    // The last binning covers no voxel: every position falls back to every point.
    std::vector<PointBins> binnings{set->bins, binPointSet(*set, glm::ivec3(-1), glm::ivec3(2), 1 << 20, UINT64_MAX, UINT32_MAX),
                                    PointBins{}};
    for (int cell : {16, 64}) // cells from world -64 to past 160 on every axis
        binnings.push_back(binPointSet(*set, glm::ivec3(-64 / cell), glm::ivec3(256 / cell), cell, UINT64_MAX, UINT32_MAX));
    size_t near = 0;
    for (int z = 0; z < kSize.z; z += 3)
        for (int y = 0; y < kSize.y; y += 3)
            for (int x = 0; x < kSize.x; x += 3) {
                const glm::vec3 p(origin + glm::ivec3(x, y, z));
                const glm::vec2 expected = everyPoint(p);
                near += expected.x < set->centreReach;
                for (const PointBins& bins : binnings)
                    ASSERT_EQ(std::bit_cast<uint64_t>(pointSetDistances(*set, bins, p)), std::bit_cast<uint64_t>(expected))
                        << "cell " << bins.cellSize << " of " << bins.cells() << " at " << p.x << "," << p.y << "," << p.z;
            }
    EXPECT_GT(near, 100u);
}

TEST(CarveTest, LimitsAreCheckedBeforeStoring) {
    Skeleton skeleton;
    skeleton.segments.push_back({{0, 0, 0}, {1000, 0, 0}, 0, SymbolType::None, 6});
    CarveLimits limits;
    limits.maxCentres = 100;
    try {
        CarveParams params;
        params.spacing = 1;
        structuralPoints(skeleton, params, limits);
        FAIL() << "no LimitError";
    } catch (const LimitError& e) {
        EXPECT_EQ(e.limit, "maxCentres");
        EXPECT_GT(e.amount, 100u);
    }
    limits = {};
    limits.maxPerCell = 10;
    try {
        carvePointSet(skeleton, CarveParams{}, 1, {0, -8, -8}, {64, 16, 16}, limits);
        FAIL() << "no LimitError";
    } catch (const LimitError& e) {
        EXPECT_EQ(e.limit, "maxPerCell");
        EXPECT_EQ(e.cap, 10u);
    }
}

// Long diagonal segments list few cells but their bounding boxes hold the whole grid: the
// binning refuses before testing 2^26 (segment, cell) pairs.
TEST(CarveTest, BinningWorkIsBoundedBeforeTesting) {
    PointSet set;
    set.segmentReach = 1;
    set.centreReach = 1;
    for (int i = 0; i < 1100; ++i)
        set.segments.push_back({glm::vec3(0.0f, float(i % 7), 0.0f), glm::vec3(511.0f), 1.0f / (3.0f * 511.0f * 511.0f)});
    try {
        binPointSetOverGrid(set, {0, 0, 0}, {512, 512, 512}, UINT64_MAX, UINT32_MAX);
        FAIL() << "no PointSetLimitError";
    } catch (const PointSetLimitError& e) {
        EXPECT_EQ(std::string(e.limit), "cellTests");
        EXPECT_GT(e.amount, kMaxPointSetCellTests);
    }
}

TEST(CarveTest, ParametersOutOfRangeAreRejected) {
    CarveParams params;
    params.maxScale = params.minScale / 2;
    EXPECT_THROW(checkCarveParams(params), UserError);
    params = {};
    params.radius = 0;
    EXPECT_THROW(checkCarveParams(params), UserError);
    params = {};
    params.yLimit = 1.5;
    EXPECT_THROW(checkCarveParams(params), UserError);
}

} // namespace
} // namespace voxc::lsystem
