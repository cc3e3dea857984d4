// The dependency radii (StageKind::dependencyRadius) are safe and tight: random grammars with
// random strides, bounds, iterations and probabilities give regions equal to the whole world (a
// radius too small would let a border effect in), and a grammar that carries solid across whole
// windows differs somewhere once the halo is one voxel short of the computed one.
#include "GridCompare.h"
#include "ProgramText.h"
#include "voxc/check/Check.h"
#include "voxc/codegen/PackageWriter.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Region.h"

#include <fmt/format.h>
#include <glm/common.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <random>

namespace voxc {
namespace {

DenseGrid interpretRegion(const Program& program, const stages::GridBox& region, glm::ivec3 halo) {
    const stages::GridBox computed = stages::haloBox(program, region, glm::max(halo, glm::ivec3(0)));
    const DenseGrid grid = interpret(stages::regionProgram(program, computed));
    return stages::cropGrid(grid, {region.min - computed.min, region.max - computed.min});
}

Program checkText(const std::string& text) {
    CheckResult result = checkSource(SourceFile("halo.vox", text));
    EXPECT_FALSE(result.hasErrors()) << result.rendered();
    return std::move(*result.program);
}

TEST(DependencyRadius, OfEachKind) {
    const Program program = checkText(R"(
world { size = [40, 24, 40]; }
start { box { min = [4, 4, 4]; max = [30, 20, 30]; } }
field f = clamp(8 - y, 0, 1);
feature drips = speleothems { kind = column; }
feature hoods = speleothems { kind = hoodoo; }
grammar g {
  stride = [1, 2, 1];
  iterations = 2;
  rule r { size = [3, 2, 1]; symbol { [PRES, IGN, IGN] [IGN, IGN, IGN] } transform { [NOP, SET 1, SET 1] [NOP, NOP, NOP] } }
}
pipeline { start; union f; drips; hoods; g; }
)");
    const stages::PipelineHalo halo = stages::pipelineHalo(program);
    ASSERT_EQ(halo.stages.size(), 5u);
    EXPECT_EQ(halo.stages[0].radius, glm::ivec3(0));
    EXPECT_EQ(halo.stages[1].radius, glm::ivec3(0));
    EXPECT_EQ(halo.stages[2].radius, glm::ivec3(0, 23, 0)); // a whole column
    EXPECT_EQ(halo.stages[3].radius, glm::ivec3(1, 23, 1));
    // x: 3 phases of a 3-wide window, each moving a cone end up to 2, twice; y: windows of 2 at
    // stride 2 never overlap, one phase, so a value never leaves its window: 1.
    EXPECT_EQ(halo.stages[4].radius.y, 1);
    EXPECT_EQ(halo.stages[4].radius.z, 0);
    EXPECT_GT(halo.stages[4].radius.x, 2);
    EXPECT_LE(halo.stages[4].radius.x, 2 * 3 * 2);
    EXPECT_EQ(halo.radius, glm::min(halo.stages[3].radius + halo.stages[2].radius + halo.stages[4].radius,
                                    program.world.size - 1));
}

// `voxc compile` writes each stage's radius and the halo into manifest.json.
TEST(DependencyRadius, IsInTheManifest) {
    CheckResult checked = checkFile(fmt::format("{}/examples/speleothems.vox", VOXC_SOURCE_DIR));
    ASSERT_FALSE(checked.hasErrors());
    const Program& program = *checked.program;
    const stages::PipelineHalo halo = stages::pipelineHalo(program);
    const nlohmann::json manifest = nlohmann::json::parse(codegen::packageManifest(compileProgram(program)));
    const auto vec = [](glm::ivec3 v) { return nlohmann::json::array({v.x, v.y, v.z}); };
    EXPECT_EQ(manifest["world"]["halo"], vec(halo.radius));
    EXPECT_EQ(halo.radius, glm::ivec3(1, program.world.size.y - 1, 1)); // the hoodoos' neighbours, whole columns
    const nlohmann::json& stages = manifest["dispatch"]["stages"];
    ASSERT_EQ(stages.size(), program.pipeline.size());
    for (size_t i = 0; i < stages.size(); ++i) EXPECT_EQ(stages[i]["dependency_radius"], vec(halo.stages[i].radius));
}

// Solid spreads across whole windows both ways, so each end of a solid run moves exactly as a cone
// end does: the farthest voxel a value can come from is reached, and a halo one short misses it.
TEST(DependencyRadius, IsTightAlongX) {
    std::vector<Rule> rules{test::makeRule("right", {"PRES, IGN, IGN"}, {"NOP, SET 1, SET 1"}),
                            test::makeRule("left", {"IGN, IGN, PRES"}, {"SET 1, SET 1, NOP"})};
    const glm::ivec3 size(48, 1, 1);
    Grammar grammar = test::makeGrammar("spread", size, rules);
    grammar.iterations = 2;
    Program program = test::makeProgram(size, {grammar});
    const glm::ivec3 radius = stages::pipelineHalo(program).radius;
    ASSERT_GT(radius.x, 0);
    EXPECT_EQ(radius.y, 0);
    size_t shortDifferences = 0;
    for (int32_t at = 10; at < 16; ++at) {
        StartShape seed;
        seed.kind = ShapeKind::Box;
        seed.min = glm::vec3(float(at), 0.0f, 0.0f);
        seed.max = glm::vec3(float(at + 6), 1.0f, 1.0f);
        program.start = {seed};
        const DenseGrid whole = interpret(program);
        for (int32_t x = 0; x < size.x; ++x) {
            const stages::GridBox voxel{{x, 0, 0}, {x + 1, 1, 1}};
            const DenseGrid expected = stages::cropGrid(whole, voxel);
            EXPECT_EQ(test::countVoxelDifferences(expected, interpretRegion(program, voxel, radius)), 0u)
                << fmt::format("seed at {}, voxel {}", at, x);
            const DenseGrid shortHalo = interpretRegion(program, voxel, radius - glm::ivec3(1, 0, 0));
            shortDifferences += expected.at({0, 0, 0}) != shortHalo.at({0, 0, 0}) ? 1 : 0;
        }
    }
    EXPECT_GT(shortDifferences, 0u) << "a halo of " << radius.x - 1 << " was enough: the radius is not tight";
}

std::string randomSymbol(std::mt19937& random) {
    static const char* kCells[] = {"IGN", "PRES", "ABS", "GEQ 0.5", "LT 0.5", "IGN"};
    return kCells[random() % 6];
}

std::string randomTransform(std::mt19937& random) {
    static const char* kCells[] = {"NOP", "SET 1", "SET 0", "ADD 0.25", "ADD -0.25", "NOP"};
    return kCells[random() % 6];
}

// Rows for a window of `size` in the printed layout (top row first, "---" between z layers).
std::vector<std::string> randomRows(std::mt19937& random, glm::ivec3 size, bool symbol) {
    std::vector<std::string> rows;
    for (int z = 0; z < size.z; ++z) {
        if (z > 0) rows.push_back("---");
        for (int y = 0; y < size.y; ++y) {
            std::string row;
            for (int x = 0; x < size.x; ++x)
                row += (x ? ", " : "") + (symbol ? randomSymbol(random) : randomTransform(random));
            rows.push_back(row);
        }
    }
    return rows;
}

Grammar randomGrammar(std::mt19937& random, glm::ivec3 world, int index) {
    std::vector<Rule> rules;
    const int ruleCount = 1 + int(random() % 4);
    for (int r = 0; r < ruleCount; ++r) {
        const glm::ivec3 window(1 + random() % 3, 1 + random() % 3, 1 + random() % 2);
        Rule rule = test::makeRule(fmt::format("r{}", r), randomRows(random, window, true),
                                   randomRows(random, window, false));
        rule.priority = int32_t(random() % 2);
        test::setWeight(rule, float(1 + random() % 4));
        test::setProbability(rule, random() % 3 == 0 ? 0.5f : 1.0f);
        rules.push_back(std::move(rule));
    }
    Grammar grammar = test::makeGrammar(fmt::format("g{}", index), world, rules);
    grammar.stride = glm::ivec3(1 + random() % 2, 1 + random() % 2, 1 + random() % 2);
    grammar.iterations = 1 + int32_t(random() % 3);
    for (int axis = 0; axis < 3; ++axis) {
        grammar.boundsMin[axis] = int32_t(random() % 4);
        grammar.boundsMax[axis] = world[axis] - int32_t(random() % 4);
    }
    if (random() % 2) grammar.clampMin = 0.0f, grammar.clampMax = 1.0f;
    return grammar;
}

// Safety: no random grammar lets the region's border reach its box through the computed halo.
TEST(DependencyRadius, IsSafeForRandomGrammars) {
    std::mt19937 random(20261202);
    const glm::ivec3 size(22, 14, 18);
    for (int trial = 0; trial < 60; ++trial) {
        std::vector<Grammar> grammars{randomGrammar(random, size, 0)};
        if (random() % 2) grammars.push_back(randomGrammar(random, size, 1));
        Program program = test::makeProgram(size, grammars, uint32_t(random()));
        program.world.origin = glm::ivec3(int32_t(random() % 40) - 20, int32_t(random() % 40) - 20, int32_t(random() % 40) - 20);
        for (int s = 0; s < 3; ++s) {
            StartShape shape;
            shape.kind = s == 2 ? ShapeKind::Sphere : ShapeKind::Box;
            shape.min = glm::vec3(random() % 10, random() % 7, random() % 9);
            shape.max = shape.min + glm::vec3(2 + random() % 10, 2 + random() % 7, 2 + random() % 9);
            shape.center = glm::vec3(random() % 22, random() % 14, random() % 18);
            shape.radius = float(2 + random() % 5);
            shape.value = s == 1 ? 0.75f : 1.0f;
            program.start.push_back(shape);
        }
        const glm::ivec3 halo = stages::pipelineHalo(program).radius;
        const DenseGrid whole = interpret(program);
        for (int r = 0; r < 3; ++r) {
            glm::ivec3 lo, hi;
            for (int axis = 0; axis < 3; ++axis) {
                lo[axis] = int32_t(random() % uint32_t(size[axis]));
                hi[axis] = lo[axis] + 1 + int32_t(random() % uint32_t(size[axis] - lo[axis]));
            }
            const stages::GridBox region{lo, hi};
            SCOPED_TRACE(fmt::format("trial {}, box ({}, {}, {})..({}, {}, {}), halo ({}, {}, {})", trial, lo.x, lo.y,
                                     lo.z, hi.x, hi.y, hi.z, halo.x, halo.y, halo.z));
            ASSERT_EQ(test::countVoxelDifferences(stages::cropGrid(whole, region), interpretRegion(program, region, halo)), 0u);
        }
    }
}

} // namespace
} // namespace voxc
