// Branch connection (lsystem-spec.md §4.4; §10 test 13) and skeleton export.
#include "TestDefinitions.h"
#include "voxc/generators/lsystem/Connect.h"
#include "voxc/generators/lsystem/Expand.h"
#include "voxc/generators/lsystem/Export.h"
#include "voxc/generators/lsystem/RuleFile.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

namespace voxc::lsystem {
namespace {

Skeleton endpointsAt(std::vector<glm::dvec3> positions) {
    Skeleton s;
    for (uint32_t i = 0; i < positions.size(); ++i) s.endpoints.push_back({positions[i], i});
    return s;
}

double distanceToSegment(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b) {
    const double t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
    return glm::length(p - (a + t * (b - a)));
}

ConnectParams always(double maxDistance) {
    ConnectParams params;
    params.chance = 1;
    params.maxDistance = maxDistance;
    params.amplitude = 4;
    params.spacing = 1;
    return params;
}

TEST(lsystem_Connect, TwoEndpointsWithinReachAreJoinedExactly) {
    const glm::dvec3 a{3.25, 7.5, -2}, b{3.25 + 6, 7.5 + 8, -2}; // 10 apart
    for (uint32_t seed = 0; seed < 20; ++seed) {
        Skeleton s = endpointsAt({a, b});
        connectBranches(s, always(16), seed, {});
        ASSERT_EQ(s.connections.size(), 1u) << seed;
        const Connection& c = s.connections[0];
        EXPECT_EQ(c.points.front(), s.endpoints[c.from].position);
        EXPECT_EQ(c.points.back(), s.endpoints[c.to].position);
        EXPECT_NE(c.from, c.to);
        EXPECT_EQ(c.points.size(), 11u);
        double largest = 0;
        for (const glm::dvec3& p : c.points) {
            const double off = distanceToSegment(p, a, b);
            EXPECT_LE(off, 4 + 1e-9);
            largest = std::max(largest, off);
        }
        EXPECT_GT(largest, 0.01) << "the curl noise moved no point";
    }
}

TEST(lsystem_Connect, EndpointsBeyondTheMaximumDistanceStayApart) {
    Skeleton s = endpointsAt({{0, 0, 0}, {10, 0, 0}});
    connectBranches(s, always(5), 1, {});
    EXPECT_TRUE(s.connections.empty());
}

TEST(lsystem_Connect, ChanceZeroConnectsNothing) {
    Skeleton s = endpointsAt({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
    ConnectParams params = always(16);
    params.chance = 0;
    connectBranches(s, params, 1, {});
    EXPECT_TRUE(s.connections.empty());
}

TEST(lsystem_Connect, ChanceOneLeavesNoDeadEndEvenWithAnOddCount) {
    for (uint32_t seed = 0; seed < 20; ++seed) {
        Skeleton s = endpointsAt({{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {0, 0, 3}, {3, 3, 3}});
        connectBranches(s, always(16), seed, {});
        std::set<uint32_t> joined;
        for (const Connection& c : s.connections) joined.insert(c.from), joined.insert(c.to);
        EXPECT_EQ(joined.size(), 5u) << seed;
        EXPECT_EQ(s.connections.size(), 3u) << seed;
    }
}

TEST(lsystem_Connect, HalfTheEndpointsStartLinesOnAverage) {
    std::vector<glm::dvec3> cluster;
    for (int i = 0; i < 400; ++i) cluster.push_back({double(i % 20), double(i / 20), 0});
    Skeleton s = endpointsAt(cluster);
    ConnectParams params = always(1000);
    params.chance = 0.5;
    connectBranches(s, params, 3, {});
    // 200 accepted endpoints on average pair into about 100 lines.
    EXPECT_NEAR(double(s.connections.size()), 100, 20);
}

TEST(lsystem_Connect, SameSeedSameLines) {
    Skeleton a = endpointsAt({{0, 0, 0}, {9, 1, 2}, {4, 4, 4}, {1, 8, 0}}), b = a, c = a;
    connectBranches(a, always(16), 5, {});
    connectBranches(b, always(16), 5, {});
    connectBranches(c, always(16), 6, {});
    EXPECT_EQ(skeletonJson(a), skeletonJson(b));
    EXPECT_NE(skeletonJson(a), skeletonJson(c));
}

TEST(lsystem_Connect, LinePointsCountAgainstTheSegmentLimit) {
    Skeleton s = endpointsAt({{0, 0, 0}, {10, 0, 0}});
    Limits limits;
    limits.maxSegments = 9;
    EXPECT_THROW(connectBranches(s, always(16), 1, limits), LimitError);
    EXPECT_THROW(connectBranches(s, [] { ConnectParams p; p.spacing = 0; return p; }(), 1, {}), UserError);
}

TEST(lsystem_Export, JsonHoldsEveryPartOfTheSkeleton) {
    Skeleton s = interpret(test::thesisDefinition(), "F[RF]F[0LF]F");
    connectBranches(s, always(16), 2, {});
    const nlohmann::json json = nlohmann::json::parse(skeletonJson(s));
    ASSERT_EQ(json["segments"].size(), 5u);
    EXPECT_EQ(json["segments"][1]["to"][0].get<double>(), s.segments[1].to.x);
    EXPECT_EQ(json["segments"][1]["branch"], 1);
    EXPECT_EQ(json["segments"][1]["type"], "none");
    EXPECT_EQ(json["endpoints"].size(), 2u);
    EXPECT_EQ(json["branches"][2]["no_connect"], true);
    ASSERT_EQ(json["connections"].size(), 1u);
    EXPECT_EQ(json["connections"][0]["points"].size(), s.connections[0].points.size());
    EXPECT_EQ(json["final_position"][0].get<double>(), 3.0);
}

TEST(lsystem_Export, ObjPolylinesFollowContinuingSegments) {
    Skeleton s = interpret(test::thesisDefinition(), "FF[RF]F");
    connectBranches(s, always(16), 2, {});
    std::istringstream in(skeletonObj(s));
    std::vector<glm::dvec3> vertices;
    std::vector<std::vector<size_t>> lines;
    for (std::string line; std::getline(in, line);) {
        std::istringstream fields(line);
        std::string tag;
        fields >> tag;
        if (tag == "v") {
            glm::dvec3 v;
            fields >> v.x >> v.y >> v.z;
            vertices.push_back(v);
        } else if (tag == "l") {
            lines.emplace_back();
            for (size_t index; fields >> index;) lines.back().push_back(index);
        }
    }
    // Trunk F F, then the branch RF, then the trunk's last F, then the one connection.
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_EQ(lines[0].size(), 3u);
    EXPECT_EQ(lines[1].size(), 2u);
    EXPECT_EQ(lines[2].size(), 2u);
    EXPECT_EQ(lines[3].size(), s.connections[0].points.size());
    EXPECT_EQ(vertices[lines[1][1] - 1], s.segments[2].to);
    EXPECT_EQ(vertices[lines[3].back() - 1], s.connections[0].points.back());
}

// §10 test 11: the same file and seed give byte-identical skeletons (deviation and connections
// included); another seed gives another one.
std::string caveSkeleton(uint32_t seed) {
    Diagnostics diagnostics;
    const auto rules = parseRuleFile(SourceFile("default.rules", std::string(defaultRuleFileText())), diagnostics);
    Definition d;
    d.productions = rules->productions;
    d.macros = rules->macros;
    d.expansions = 3;
    d.seed = seed;
    d.params.angleDeviation = 15;
    const Expansion e = expand(d);
    Skeleton s = interpret(d, e.symbols, e.types);
    connectBranches(s, ConnectParams{}, d.seed, d.limits);
    return skeletonJson(s) + skeletonObj(s);
}

TEST(lsystem_Export, SameSeedGivesByteIdenticalSkeletons) {
    const std::string first = caveSkeleton(7);
    EXPECT_EQ(first, caveSkeleton(7));
    EXPECT_NE(first, caveSkeleton(8));
    EXPECT_NE(first.find("\"connections\""), std::string::npos);
}

} // namespace
} // namespace voxc::lsystem
