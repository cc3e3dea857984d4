// Interval analysis through bounded noise: a noise terrain's chunks far above the surface are
// proven air and far below proven rock (fbm is bounded by 1.5 sum gain^k), every chunk called
// constant is that float at every voxel as the interpreter evaluates it, and chunks near the
// surface still evaluate.
#include "voxc/check/Check.h"
#include "voxc/interp/FieldEval.h"
#include "voxc/ir/Lower.h"
#include "voxc/ir/passes/ClassifyFieldChunks.h"

#include <gtest/gtest.h>

#include <bit>

namespace voxc::ir {
namespace {

// Height 64 + 8 fbm (|fbm| <= 1.5 * 1.875 with 4 octaves of gain 1/2): the surface lies in
// y in [41.5, 86.5], so with chunk 16 rows y < 32 are rock and rows y >= 96 are air.
constexpr const char* kTerrain = R"(
world { size = [64, 160, 48]; origin = [-20, 0, 37]; chunk = 16; seed = 3; }
field ground =
  let h = 64 + 8 * fbm(vec3(wx, 0, wz) * 0.03, 4, 2.0, 0.5, 5) in
  clamp(h - y, 0, 1);
field caves =
  let n = turbulence(wp * 0.05, 3, 2.0, 0.5, 9) + 0.2 * sin(wx * 0.1) + 0.1 * worley_f1(wp * 0.1, 2) in
  smoothstep(0.2, 0.3, n + (y > 120 ? 9.0 : 0.0));
)";

struct Row {
    size_t constant = 0, total = 0;
    float value = -1;      // the constant's value when every chunk of the row has the same one
    bool mixed = false;
};

TEST(ir_NoiseSkipping, ChunksFarFromANoiseSurfaceAreProvenAirOrRock) {
    CheckResult checked = checkSource(SourceFile("terrain.vox", kTerrain));
    ASSERT_FALSE(checked.hasErrors()) << checked.rendered();
    const Program& program = *checked.program;
    const IrModule module = lowerProgram(program, {});
    ASSERT_EQ(module.fields.size(), 2u);

    // ground: per chunk row (y / 16), how many chunks are constant and with which value.
    FieldEvaluator ground(program.fields[0], program.world.origin);
    std::vector<Row> rows(10);
    for (const FieldChunk& chunk : classifyFieldChunks(module.world, module.fields[0])) {
        Row& row = rows[size_t(chunk.chunk.y)];
        ++row.total;
        if (!chunk.constant) continue;
        ++row.constant;
        row.mixed = row.mixed || (row.value >= 0 && row.value != chunk.value);
        row.value = chunk.value;
        for (int z = chunk.localMin.z; z < chunk.localMax.z; ++z)
            for (int y = chunk.localMin.y; y < chunk.localMax.y; ++y)
                for (int x = chunk.localMin.x; x < chunk.localMax.x; ++x)
                    ASSERT_EQ(std::bit_cast<uint32_t>(ground.density({x, y, z})), std::bit_cast<uint32_t>(chunk.value))
                        << "at " << x << "," << y << "," << z;
    }
    for (size_t y = 0; y < rows.size(); ++y) {
        SCOPED_TRACE("chunk row " + std::to_string(y));
        if (y < 2 || y >= 6) {
            EXPECT_EQ(rows[y].constant, rows[y].total); // proven: the whole row skips the evaluation
            EXPECT_FALSE(rows[y].mixed);
            EXPECT_EQ(rows[y].value, y < 2 ? 1.0f : 0.0f);
        }
        if (y == 3 || y == 4) {
            EXPECT_EQ(rows[y].constant, 0u); // the surface runs through these
        }
    }

    // caves: turbulence, sin and worley are bounded, so the rows above y = 120 are exactly 1.
    FieldEvaluator caves(program.fields[1], program.world.origin);
    size_t constantCaves = 0;
    for (const FieldChunk& chunk : classifyFieldChunks(module.world, module.fields[1])) {
        if (chunk.localMin.y >= 128) {
            EXPECT_TRUE(chunk.constant) << "chunk row " << chunk.chunk.y;
        }
        if (!chunk.constant) continue;
        ++constantCaves;
        EXPECT_EQ(chunk.value, 1.0f);
        for (int z = chunk.localMin.z; z < chunk.localMax.z; ++z)
            for (int y = chunk.localMin.y; y < chunk.localMax.y; ++y)
                for (int x = chunk.localMin.x; x < chunk.localMax.x; ++x)
                    ASSERT_EQ(std::bit_cast<uint32_t>(caves.density({x, y, z})), std::bit_cast<uint32_t>(chunk.value));
    }
    EXPECT_GT(constantCaves, 0u);
}

} // namespace
} // namespace voxc::ir
