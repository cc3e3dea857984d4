// The lsystem_cave carve on Vulkan (lavapipe) against the interpreter (docs/architecture.md
// "Carving"): bit-identical voxels at chunk sizes 8/16/32/64 and an odd origin (spec §10
// test 16), the clearance guarantee and bounded carving on the device (tests 14, 15), and chunks
// far from the skeleton proven constant by interval analysis. The bit-for-bit cases also check that
// the field kernel looks the point set up along the column (ordinary lists one entry per loop
// iteration, dense and full ones eight).
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

// The grid a run of `program` leaves on lavapipe, after checking that its carve's field kernel
// looks the point set up for the voxels of a column together (point_set_column.glsl), `block`
// list entries per loop iteration, and nowhere per voxel.
DenseGrid runColumnLookupsOnLavapipe(const Program& program, int block) {
    KernelPackage package = compileProgram(program, {});
    int columnKernels = 0;
    for (const Kernel& kernel : package.kernels) {
        EXPECT_EQ(kernel.glsl.find("= pointSetDistances(0, "), std::string::npos) << kernel.name;
        if (kernel.glsl.find("pointSetColumnFill(0, 0, pointSetColumnX0, pointSetColumnZ0, blockY, blockEnd") ==
            std::string::npos)
            continue;
        ++columnKernels;
        EXPECT_NE(kernel.glsl.find(fmt::format("#define POINT_SET_BLOCK {}\n", block)), std::string::npos) << kernel.name;
    }
    EXPECT_EQ(columnKernels, 1);
    VulkanExecutor executor(test::lavapipe(), std::move(package));
    return executor.run().grid.toDense();
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
        EXPECT_EQ(test::countBitDifferences(expected, runColumnLookupsOnLavapipe(program, 1)), 0u) << "chunk " << chunk;
    }
}

// A dense network: short steps and centres every quarter voxel make thousands of centres in one
// cell's list (2,832 here; lavapipe used to leave the list loops once an invocation had looped
// 65,535 times, from about 1,500 centres per cell on).
std::string denseCaveProgram(int expansions, const std::string& keys, const std::string& origin = "[0, 0, 0]") {
    return fmt::format(R"(
world {{ size = [48, 32, 48]; origin = {}; seed = 3; }}
start {{ fill {{ value = 1; }} }}
lsystem net {{
  axiom = "Z"; expansions = {}; angle = 45; step = 0.5; start = [24, 16, 24];
  production Z {{ "FZ[RFZ]FZ[LFZ[RF]]"; }}
}}
feature tunnels = lsystem_cave {{ lsystem = net; {} }}
pipeline {{ start; subtract tunnels; }}
)",
                       origin, expansions, keys);
}

const PointSet& pointSetOf(const Program& program) {
    const PointSet* set = nullptr;
    for (const FieldNode& node : program.fields.back().nodes)
        if (node.kind == FieldNode::Kind::PointSet) set = node.pointSet.get();
    EXPECT_NE(set, nullptr);
    return *set;
}

uint32_t longestList(const std::vector<uint32_t>& start) {
    uint32_t longest = 0;
    for (size_t i = 0; i + 1 < start.size(); ++i) longest = std::max(longest, start[i + 1] - start[i]);
    return longest;
}

TEST(vulkan_LsystemCarve, DenseNetworksMatchTheInterpreterAtEveryChunkSize) {
    CheckResult result = checked(denseCaveProgram(4, "radius = 8; spacing = 0.25; clearance = 1;"));
    ASSERT_TRUE(result.program);
    Program program = *result.program;
    EXPECT_GT(longestList(pointSetOf(program).bins.centreStart), 2000u);
    const DenseGrid expected = interpret(program);
    for (int chunk : {8, 16, 32, 64}) {
        program.world.chunkSize = chunk;
        EXPECT_EQ(test::countBitDifferences(expected, runColumnLookupsOnLavapipe(program, 8)), 0u) << "chunk " << chunk;
    }
    // At an odd origin the cells of the lists and the chunks straddle the network differently
    // (one chunk size: the lists' code is the same at every size).
    CheckResult odd = checked(denseCaveProgram(4, "radius = 8; spacing = 0.25; clearance = 1;", "[-7, 3, 5]"));
    ASSERT_TRUE(odd.program);
    EXPECT_GT(longestList(pointSetOf(*odd.program).bins.centreStart), 2000u);
    EXPECT_EQ(test::countBitDifferences(interpret(*odd.program), runColumnLookupsOnLavapipe(*odd.program, 8)), 0u);
}

// The worst lists the checker accepts: kMaxPointSetPerCell centres and as many segments, packed so
// tight that no lower bound stops a loop early (every voxel of a cell reads its whole lists), in
// the carve of a 64-high world (long columns) at every chunk size.
TEST(vulkan_LsystemCarve, ListsAtTheLimitMatchTheInterpreter) {
    CheckResult result = checked(caveProgram("size = [24, 64, 24]; seed = 4;", "radius = 2; clearance = 1;"));
    ASSERT_TRUE(result.program);
    Program program = *result.program;
    auto set = std::make_shared<PointSet>(pointSetOf(program));
    set->centres.clear();
    set->centreScales.clear();
    set->segments.clear();
    const uint32_t n = kMaxPointSetPerCell;
    for (uint32_t i = 0; i < n; ++i) {
        // Within 0.01 of (12.5, 30.5, 12.5): the same distance, to a float ulp or so, for all.
        const float jitter = 0.01f * float(i % 97) / 97.0f;
        set->centres.push_back({12.5f + jitter, 30.5f - jitter, 12.5f + 0.5f * jitter});
        set->centreScales.push_back(0.125f); // radius 8
        PointSetSegment segment;
        segment.from = {12.5f - jitter, 31.5f, 12.5f + jitter};
        segment.delta = {0.0f, 0.0f, 0.0f};
        set->segments.push_back(segment);
    }
    set->bins = binPointSetOverGrid(*set, program.world.origin, program.world.size, kMaxPointSetListEntries, n);
    ASSERT_EQ(longestList(set->bins.centreStart), n);
    ASSERT_EQ(longestList(set->bins.segmentStart), n);
    for (FieldNode& node : program.fields.back().nodes)
        if (node.kind == FieldNode::Kind::PointSet) node.pointSet = set;
    EXPECT_THROW(binPointSetOverGrid(*set, program.world.origin, program.world.size, kMaxPointSetListEntries, n - 1),
                 PointSetLimitError);
    const DenseGrid expected = interpret(program);
    size_t air = 0;
    for (float d : expected.data()) air += d < 0.5f;
    EXPECT_GT(air, 1000u);
    for (int chunk : {8, 64}) {
        program.world.chunkSize = chunk;
        EXPECT_EQ(test::countBitDifferences(expected, runColumnLookupsOnLavapipe(program, 8)), 0u) << "chunk " << chunk;
    }
}

// One past the limit: the checker refuses the file at the carve's `lsystem` key (E0012).
TEST(vulkan_LsystemCarve, ListsPastTheLimitAreALocatedE0012) {
    const CheckResult result =
        checkSource(SourceFile("carve.vox", denseCaveProgram(5, "radius = 8; spacing = 0.25; clearance = 1;")));
    ASSERT_TRUE(result.hasErrors());
    const std::string text = result.rendered();
    EXPECT_NE(text.find("carve.vox:8:44: error E0012"), std::string::npos) << text;
    EXPECT_NE(text.find("8193 (CarveLimits::maxPerCell is 8192)"), std::string::npos) << text;
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
