// The lsystem_cave carve on Vulkan (lavapipe) against the interpreter (docs/lsystem.md
// "Carving"): bit-identical voxels at chunk sizes 8/16/32/64 and an odd origin (spec §10
// test 16), the clearance guarantee and bounded carving on the device (tests 14, 15), and chunks
// far from the skeleton proven constant by interval analysis.
#include "Lavapipe.h"
#include "GridCompare.h"
#include "voxc/check/Check.h"
#include "voxc/generators/lsystem/Connect.h"
#include "voxc/generators/lsystem/Expand.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/ir/passes/ClassifyFieldChunks.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace voxc {
namespace {

CheckResult checked(const std::string& text) {
    CheckResult result = checkSource(SourceFile("carve.vox", text));
    EXPECT_FALSE(result.hasErrors()) << result.rendered();
    return result;
}

// Grammar (3), three expansions, in rock, its production of `type`; `keys` adds feature keys,
// `world` the world's.
std::string caveProgram(const std::string& world, const std::string& keys, const std::string& start = "[4, 9, 20]",
                        const std::string& type = "none") {
    return fmt::format(R"(
world {{ {} }}
start {{ fill {{ value = 1; }} }}
lsystem net {{
  expansions = 3; angle = 45; step = 2; start = {};
  production Z {{ "FZ[RFZ]FZ[LFZ[RF]]" {} 1; }}
  connect {{ chance = 1; max_distance = 12; }}
}}
feature tunnels = lsystem_cave {{ lsystem = net; {} }}
pipeline {{ start; subtract tunnels; }}
)",
                       world, start, type, keys);
}

lsystem::Skeleton skeletonOf(const CheckResult& result) {
    const CheckedLsystem& net = result.lsystems.at(0);
    const lsystem::Expansion e = lsystem::expand(net.definition);
    lsystem::Skeleton skeleton = lsystem::interpret(net.definition, e.symbols, e.types);
    lsystem::connectBranches(skeleton, net.connect, net.definition.seed, net.definition.limits);
    return skeleton;
}

double distanceToSkeleton(const lsystem::Skeleton& skeleton, glm::dvec3 p) {
    const auto segment = [&](glm::dvec3 a, glm::dvec3 b) {
        const glm::dvec3 d = b - a;
        const double len2 = glm::dot(d, d);
        const double t = len2 > 0 ? std::clamp(glm::dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
        return glm::length(p - (a + t * d));
    };
    double best = INFINITY;
    for (const lsystem::Segment& s : skeleton.segments) best = std::min(best, segment(s.from, s.to));
    for (const lsystem::Connection& line : skeleton.connections)
        for (size_t k = 0; k + 1 < line.points.size(); ++k)
            best = std::min(best, segment(line.points[k], line.points[k + 1]));
    return best;
}

// Spec test 16 with an odd, negative origin: chunks straddle the grid's edges and the lists of
// the device (its chunk size) differ from the interpreter's (the checked chunk size).
TEST(vulkan_LsystemCarve, MatchesTheInterpreterAtEveryChunkSize) {
    // Room segments (radius 5) and connection lines (radius 3): centres of two sizes.
    CheckResult result = checked(caveProgram("size = [45, 23, 41]; origin = [-13, -6, 5]; seed = 3;",
                                             "radius = 3; room_radius = 5; clearance = 1;", "[-10, 4, 25]", "room"));
    ASSERT_TRUE(result.program);
    Program program = *result.program;
    const DenseGrid expected = interpret(program);
    size_t air = 0;
    for (float d : expected.data()) air += d < 0.5f;
    EXPECT_GT(air, 500u); // the carve reached the grid
    for (int chunk : {8, 16, 32, 64}) {
        program.world.chunkSize = chunk;
        EXPECT_EQ(test::countBitDifferences(expected, test::runOnLavapipe(program)), 0u) << "chunk " << chunk;
    }
}

// Spec tests 14 and 15 on the device, over noise settings that distort hard.
TEST(vulkan_LsystemCarve, ClearanceAndSupportHoldOnTheDevice) {
    struct Setting {
        const char* keys;
        double clearance;
    };
    const Setting settings[] = {
        {"radius = 2; clearance = 1.5; simplex_amplitude = 4; voronoi_amplitude = 4; min_scale = 1.5; max_scale = 9;", 1.5},
        {"radius = 5; clearance = 1; curl_amplitude = 8; y_limit = 1; min_scale = 0.5; voronoi_frequency = 0.3;", 1.0},
        {"radius = 1; spacing = 3; clearance = 2; simplex_frequency = 0.4; simplex_amplitude = 2;", 2.0},
    };
    for (const auto& [keys, clearance] : settings) {
        CheckResult result = checked(caveProgram("size = [48, 24, 48]; chunk = 16; seed = 5;", keys));
        ASSERT_TRUE(result.program);
        const lsystem::Skeleton skeleton = skeletonOf(result);
        const Field& field = result.program->fields.back();
        const PointSet* set = nullptr;
        for (const FieldNode& node : field.nodes)
            if (node.kind == FieldNode::Kind::PointSet) set = node.pointSet.get();
        ASSERT_NE(set, nullptr);
        // Centre i supports 2 R_i / m_min + 1 voxels: its scale is 1 / R_i, the reach 2.2 / m_min.
        const auto support = [&](size_t i) { return set->centreReach / 2.2 * 2.0 / set->centreScales[i] + 1.0; };
        const DenseGrid grid = test::runOnLavapipe(*result.program);
        int near = 0, far = 0;
        for (int z = 0; z < 48; ++z)
            for (int y = 0; y < 24; ++y)
                for (int x = 0; x < 48; ++x) {
                    const glm::dvec3 p(x, y, z);
                    const double d = distanceToSkeleton(skeleton, p);
                    const float density = grid.at({x, y, z});
                    if (d < clearance - 1e-4) {
                        ++near;
                        ASSERT_LT(density, 0.5f) << keys << " at " << x << "," << y << "," << z;
                    } else if (d > 1.125 * clearance) {
                        bool inside = false;
                        for (size_t i = 0; i < set->centres.size(); ++i)
                            inside = inside || glm::length(p - glm::dvec3(set->centres[i])) <= support(i);
                        if (inside) continue;
                        ++far;
                        ASSERT_EQ(density, 1.0f) << keys << " at " << x << "," << y << "," << z;
                    }
                }
        EXPECT_GT(near, 0) << keys;
        EXPECT_GT(far, 0) << keys;
    }
}

// Interval analysis proves the carve exactly 0 in chunks beyond every point's reach, so a
// subtract there leaves the rock untouched and is not dispatched.
TEST(vulkan_LsystemCarve, FarChunksAreConstantZero) {
    CheckResult result = checked(caveProgram("size = [128, 32, 128]; chunk = 16; seed = 9;", "radius = 2;"));
    ASSERT_TRUE(result.program);
    const Field& field = result.program->fields.back();
    const ir::IrField irField{field.name, field.loc, field.nodes, field.root, {}};
    size_t constantZero = 0, evaluated = 0;
    for (const ir::FieldChunk& chunk : ir::classifyFieldChunks(result.program->world, irField)) {
        if (chunk.constant) {
            EXPECT_EQ(chunk.value, 0.0f);
            ++constantZero;
        } else {
            ++evaluated;
        }
    }
    EXPECT_GT(evaluated, 0u);
    EXPECT_GT(constantZero, evaluated); // the network fills a corner of the grid
}

} // namespace
} // namespace voxc
