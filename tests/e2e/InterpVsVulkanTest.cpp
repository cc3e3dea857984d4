// Every example, run by the interpreter and by the Vulkan path at chunk sizes 8, 16 and 32 and
// with the grid origin shifted by zero, a negative and a far offset (so chunks straddle and floor division
// of negative coordinates matters), must give bit-identical voxels. Field stages too: every
// record they use is exact on lavapipe except sin and cos, which FieldsWithinRecordTolerance
// compares within the records' tolerances.
#include "Lavapipe.h"
#include "voxc/builtins/Functions.h"
#include "GridCompare.h"
#include "voxc/check/Check.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Solve.h"
#include "voxc/grid/Grid.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace voxc {
namespace interp_vs_vulkan_test {

// `name` is an example in examples/ or, with a "cases/" prefix, a file beside this test.
Program loadExample(const std::string& name) {
    const bool testCase = name.rfind("cases/", 0) == 0;
    CheckResult result = checkFile(testCase ? fmt::format("{}/tests/e2e/{}.vox", VOXC_SOURCE_DIR, name)
                                            : fmt::format("{}/examples/{}.vox", VOXC_SOURCE_DIR, name));
    EXPECT_FALSE(result.hasErrors());
    return std::move(*result.program);
}

struct Case {
    std::string example;
    glm::ivec3 origin;
};

void PrintTo(const Case& c, std::ostream* out) {
    *out << fmt::format("{} at origin ({}, {}, {})", c.example, c.origin.x, c.origin.y, c.origin.z);
}

class InterpVsVulkan : public ::testing::TestWithParam<Case> {};

TEST_P(InterpVsVulkan, BitIdenticalAtEveryChunkSize) {
    Program program = loadExample(GetParam().example);
    program.world.origin += GetParam().origin;
    stages::solveBlocks(program); // once, not per chunk size (curves tables are grid-local)
    test::expectLavapipeMatchesAtEveryChunkSize(program, interpret(program));
}

// cases/field_trig.vox: its field is 0.5 + 0.25 * sin(..) * cos(..), so each voxel may differ by
// at most the sum of the tolerances of the inexact calls in the field (the factors are <= 1).
TEST(InterpVsVulkanFields, FieldsWithinRecordTolerance) {
    Program program = loadExample("cases/field_trig");
    ASSERT_EQ(program.fields.size(), 1u);
    float bound = 0.0f;
    for (const FieldNode& node : program.fields[0].nodes)
        if (node.kind == FieldNode::Kind::Call) bound += functions()[node.function].tolerance;
    ASSERT_GT(bound, 0.0f); // sin and cos promise no exactness
    const DenseGrid expected = interpret(program);
    for (int chunk : {8, 32}) {
        SCOPED_TRACE(fmt::format("chunk {}", chunk));
        program.world.chunkSize = chunk;
        const DenseGrid actual = test::runOnLavapipe(program);
        float largest = 0.0f;
        const glm::ivec3 size = expected.size();
        for (int z = 0; z < size.z; ++z)
            for (int y = 0; y < size.y; ++y)
                for (int x = 0; x < size.x; ++x)
                    largest = std::max(largest, std::fabs(expected.at({x, y, z}) - actual.at({x, y, z})));
        EXPECT_LE(largest, bound);
    }
}

std::vector<Case> cases() {
    std::vector<Case> all;
    for (const char* example : {"overhang", "cave_grammar", "terrain", "scene", "fields", "arch", "cave", "cliff", "curves_cliff", "curves_cave", "curves_terrace", "valley", "mountains", "canyon", "imported_ridge", "boulders", "carved_ridge", "tutorial/06_valley", "cases/priorities",
                                "cases/field_modes", "cases/materials_grammar", "cases/materials_fields",
                                "cases/nonfinite", "cases/symmetry", "cases/aggregates", "cases/column_noise",
                                "cases/noise_skip"})
        for (glm::ivec3 origin : {glm::ivec3(0, 0, 0), glm::ivec3(-37, -5, -100), glm::ivec3(100003, 7, -65541)})
            all.push_back({example, origin});
    return all;
}

INSTANTIATE_TEST_SUITE_P(Examples, InterpVsVulkan, ::testing::ValuesIn(cases()), [](const auto& info) {
    const glm::ivec3 o = info.param.origin;
    std::string example = info.param.example;
    std::replace(example.begin(), example.end(), '/', '_');
    return fmt::format("{}_origin_{}_{}_{}", example, o.x < 0 ? "m" + std::to_string(-o.x) : std::to_string(o.x),
                       o.y < 0 ? "m" + std::to_string(-o.y) : std::to_string(o.y),
                       o.z < 0 ? "m" + std::to_string(-o.z) : std::to_string(o.z));
});

} // namespace interp_vs_vulkan_test
} // namespace voxc
