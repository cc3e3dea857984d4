// The per-chunk interval analysis fires on the feature examples (most chunks of the arch are
// provably air), and every chunk it calls constant is that exact float at every voxel, as the
// interpreter evaluates it.
#include "voxc/check/Check.h"
#include "voxc/interp/FieldEval.h"
#include "voxc/ir/Lower.h"
#include "voxc/ir/passes/ClassifyFieldChunks.h"

#include <gtest/gtest.h>

#include <bit>
#include <fstream>
#include <optional>
#include <sstream>

namespace voxc::ir {
namespace {

std::optional<Program> checkExample(const std::string& name, const std::string& worldOverride = "") {
    std::ifstream in(std::string(VOXC_EXAMPLES_DIR) + "/" + name);
    std::stringstream text;
    text << in.rdbuf();
    std::string source = text.str();
    if (!worldOverride.empty()) {
        const size_t start = source.find("world {"), end = source.find('}', start);
        source.replace(start, end + 1 - start, worldOverride);
    }
    CheckResult result = checkSource(SourceFile(name, source));
    EXPECT_FALSE(result.hasErrors()) << result.rendered();
    return std::move(result.program);
}

struct Counts {
    size_t constant = 0, total = 0;
};

// Classifies every field of the program; checks each constant chunk voxel by voxel.
Counts classifyAndVerify(const Program& program) {
    const IrModule module = lowerProgram(program, {});
    Counts counts;
    for (size_t f = 0; f < module.fields.size(); ++f) {
        FieldEvaluator evaluator(program.fields[f], program.world.origin);
        for (const FieldChunk& chunk : classifyFieldChunks(module.world, module.fields[f])) {
            ++counts.total;
            if (!chunk.constant) continue;
            ++counts.constant;
            for (int z = chunk.localMin.z; z < chunk.localMax.z; ++z)
                for (int y = chunk.localMin.y; y < chunk.localMax.y; ++y)
                    for (int x = chunk.localMin.x; x < chunk.localMax.x; ++x)
                        EXPECT_EQ(std::bit_cast<uint32_t>(evaluator.density({x, y, z})),
                                  std::bit_cast<uint32_t>(chunk.value))
                            << module.fields[f].name << " at " << x << "," << y << "," << z;
        }
    }
    return counts;
}

TEST(ir_ClassifyFieldChunks, MostArchChunksAreConstantAir) {
    const auto program = checkExample("arch.vox", "world { size = [64, 64, 64]; chunk = 8; }");
    ASSERT_TRUE(program);
    const Counts counts = classifyAndVerify(*program);
    EXPECT_EQ(counts.total, 512u);
    EXPECT_GT(counts.constant, counts.total / 2) << counts.constant << " of " << counts.total;
}

TEST(ir_ClassifyFieldChunks, ConstantChunksMatchTheInterpreterAtOddOrigins) {
    for (const std::string example : {"arch.vox", "cave.vox", "cliff.vox", "scene.vox", "fields.vox"})
        for (const std::string& world :
             {std::string("world { size = [40, 36, 44]; origin = [-13, -70, 5]; chunk = 8; }"),
              std::string("world { size = [48, 40, 40]; origin = [1000003, 7, -2000001]; chunk = 16; }")}) {
            SCOPED_TRACE(example + " " + world);
            const auto program = checkExample(example, world);
            ASSERT_TRUE(program);
            classifyAndVerify(*program);
        }
}

} // namespace
} // namespace voxc::ir
