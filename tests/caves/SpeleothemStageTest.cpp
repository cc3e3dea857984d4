// Speleothem stages from .vox source: the interpreter and Vulkan (lavapipe) agree bit for bit at
// chunk sizes 8/16/32/64 and odd origins (spec test 17 included: columns join across chunk
// borders), every kind, materials, and keep_clear never writes the carve's clearance.
#include "CheckedProgram.h"
#include "Lavapipe.h"
#include "voxc/check/Check.h"
#include "voxc/codegen/PackageWriter.h"
#include "voxc/grid/Grid.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/core/Errors.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/DispatchPlan.h"
#include "voxc/vulkan/Executor.h"

#include "GridCompare.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace voxc {
namespace {

Program checked(const std::string& text) { return test::checkedProgram("speleothems.vox", text); }

// The interpreter's grid, after checking Vulkan gives the same bits at every chunk size.
DenseGrid agreeAtEveryChunkSize(Program program) {
    const DenseGrid expected = interpret(program);
    for (int chunk : {8, 16, 32, 64}) {
        SCOPED_TRACE(fmt::format("chunk {}", chunk));
        program.world.chunkSize = chunk;
        EXPECT_EQ(test::countVoxelDifferences(expected, test::runOnLavapipe(program)), 0u);
    }
    return expected;
}

// Spec test 17: an air slab y in [10, 40] between rock floor and ceiling, every run spawning
// with reach 1, chunk borders at every size crossing the slab.
std::string slabSource(std::string_view kind, glm::ivec3 origin) {
    return fmt::format(R"(world {{ size = [37, 52, 29]; origin = [{}, {}, {}]; seed = 3; }}
material rock {{ id = 1; }}
material flowstone {{ id = 2; }}
start {{
  fill {{ value = 1; material = rock; }}
  box {{ min = [0, 10, 0]; max = [37, 41, 29]; value = 0; }}
}}
feature drips = speleothems {{
  kind = {};
  cluster_low = -1; cluster_high = 1;
  spawn_threshold = -1; growth = 1000;
  material = flowstone;
}}
pipeline {{ start; drips; }}
)",
                       origin.x, origin.y, origin.z, kind);
}

TEST(caves_SpeleothemStage, ColumnsJoinAcrossChunkBorders) { // spec test 17
    for (std::string_view kind : {"column", "hoodoo"}) {
        SCOPED_TRACE(kind);
        Program program = checked(slabSource(kind, {-13, 5, 21}));
        Program before = program;
        before.pipeline.pop_back();
        const DenseGrid slab = interpret(before);
        const DenseGrid grid = agreeAtEveryChunkSize(program);
        for (int z = 0; z < 29; ++z)
            for (int x = 0; x < 37; ++x)
                for (int y = 10; y <= 40; ++y) {
                    ASSERT_EQ(slab.at({x, y, z}), 0.0f); // the start block's air slab
                    ASSERT_GE(grid.at({x, y, z}), 0.5f) << x << "," << y << "," << z;
                    ASSERT_EQ(grid.materialAt({x, y, z}), 2);
                }
    }
}

// A noise cave (rock with fBm air pockets): the default spawn rule, so only some runs grow.
std::string caveSource(std::string_view kind, std::string_view extra) {
    return fmt::format(R"(world {{ size = [40, 48, 36]; origin = [-7, 3, 11]; seed = 11; }}
material rock {{ id = 1; }}
material flowstone {{ id = 2; }}
start {{ fill {{ value = 1; material = rock; }} }}
field pockets = 0.5 + 2 * fbm(vec3(wx, wy * 1.5, wz) * 0.06, 3, 2, 0.5, 5);
feature drips = speleothems {{ kind = {}; cluster_low = -1; spawn_threshold = 0.2; {} }}
pipeline {{ start; subtract pockets; drips material flowstone; }}
)",
                       kind, extra);
}

TEST(caves_SpeleothemStage, EveryKindAgreesWithTheInterpreter) {
    for (std::string_view kind : {"stalactite", "stalagmite", "column", "hoodoo"}) {
        SCOPED_TRACE(kind);
        const Program program = checked(caveSource(kind, "taper = 2; growth = 0.8;"));
        Program before = program;
        before.pipeline.pop_back();
        const DenseGrid carved = interpret(before);
        const DenseGrid grown = agreeAtEveryChunkSize(program);
        size_t written = 0;
        for (size_t i = 0; i < grown.data().size(); ++i) written += grown.data()[i] != carved.data()[i];
        EXPECT_GT(written, 50u); // the stage did grow something here
    }
}

// keep_clear: an L-system carve's clearance radius stays air through the speleothem stage.
TEST(caves_SpeleothemStage, KeepClearLeavesTheClearanceAir) {
    const std::string text = R"(world { size = [64, 40, 48]; origin = [0, 0, 0]; seed = 7; }
start { fill { value = 1; } }
lsystem net {
  axiom = "Z"; expansions = 2; angle = 45; step = 5; start = [8, 20, 24];
  production Z { "FZ[RFZ]FZ"; }
}
feature tunnels = lsystem_cave { lsystem = net; radius = 4; clearance = 2; }
feature drips = speleothems {
  kind = hoodoo; cluster_low = -1; spawn_threshold = -1; growth = 1000; keep_clear = tunnels;
}
pipeline { start; subtract tunnels; drips; }
)";
    Program program = checked(text);
    ASSERT_EQ(program.speleothems.size(), 1u);
    ASSERT_NE(program.speleothems[0].clearance, nullptr);
    const PointSet& set = *program.speleothems[0].clearance;
    const DenseGrid grid = agreeAtEveryChunkSize(program);
    size_t clear = 0, filled = 0;
    for (int z = 0; z < 48; ++z)
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 64; ++x) {
                if (pointSetClearance(set, glm::vec3(x, y, z))) {
                    EXPECT_LT(grid.at({x, y, z}), 0.5f) << x << "," << y << "," << z;
                    ++clear;
                }
            }
    // Without keep_clear the same stage fills the tunnels from floor to ceiling.
    Program unprotected = checked(std::string(text).replace(text.find("keep_clear = tunnels;"), 21, ""));
    const DenseGrid blocked = interpret(unprotected);
    for (int z = 0; z < 48; ++z)
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 64; ++x)
                filled += pointSetClearance(set, glm::vec3(x, y, z)) && blocked.at({x, y, z}) >= 0.5f;
    EXPECT_GT(clear, 100u);
    EXPECT_GT(filled, 100u);
}

// Spec test 14 after a speleothem stage, on the interpreter: for several grammars, seeds and
// brush settings, every voxel within the carve's clearance is still air after hoodoos and
// columns that would otherwise fill every closed run from floor to ceiling.
TEST(caves_SpeleothemStage, ClearanceHoldsForEveryGrammarAndSeed) {
    const char* productions[] = {"FZ[RFZ]FZ", "FUFZ[LFDZ]", "FFZ[RRFZ][LLFZ]"};
    size_t clearVoxels = 0;
    for (const char* production : productions)
        for (uint32_t seed : {1u, 9u, 23u}) {
            SCOPED_TRACE(fmt::format("{} seed {}", production, seed));
            const Program program = checked(fmt::format(
                R"(world {{ size = [48, 32, 40]; origin = [-5, 2, 3]; seed = {}; }}
start {{ fill {{ value = 1; }} }}
lsystem net {{ axiom = "Z"; expansions = 2; step = 4; start = [2, 18, 22]; production Z {{ "{}"; }} }}
feature tunnels = lsystem_cave {{ lsystem = net; radius = 3; clearance = 2; simplex_amplitude = 0.6; }}
feature columns = speleothems {{ kind = column; cluster_low = -1; spawn_threshold = -1; growth = 1000; keep_clear = tunnels; }}
feature hoodoos = speleothems {{ kind = hoodoo; cluster_low = -1; spawn_threshold = -1; taper = 0; keep_clear = tunnels; }}
pipeline {{ start; subtract tunnels; columns; hoodoos; }}
)",
                seed, production));
            const PointSet& set = *program.speleothems.at(0).clearance;
            const DenseGrid grid = interpret(program);
            const glm::ivec3 origin = program.world.origin;
            for (int z = 0; z < 40; ++z)
                for (int y = 0; y < 32; ++y)
                    for (int x = 0; x < 48; ++x)
                        if (pointSetClearance(set, glm::vec3(origin + glm::ivec3(x, y, z)))) {
                            ASSERT_LT(grid.at({x, y, z}), 0.5f) << x << "," << y << "," << z;
                            ++clearVoxels;
                        }
        }
    EXPECT_GT(clearVoxels, 1000u);
}

// The package lists the stage as a prepass and a grid pass sharing the scratch buffer's air mask.
TEST(caves_SpeleothemStage, ManifestDescribesThePasses) {
    const KernelPackage package = compileProgram(checked(slabSource("hoodoo", {0, 0, 0})), {});
    ASSERT_EQ(package.stages.size(), 2u);
    const StagePlan& stage = package.stages[1];
    EXPECT_EQ(stage.kind, "speleothems");
    EXPECT_EQ(package.kernels.at(stage.prepassKernel).name, "speleothem_mask");
    EXPECT_EQ(package.kernels.at(stage.gridKernel).name, "drips_speleothems_m2");
    EXPECT_EQ(stage.scratchWords, uint64_t(37) * 29 * 2); // 52 voxels high: two words per column
    const std::string manifest = codegen::packageManifest(package);
    for (std::string_view expected : {"\"prepass_kernel\": \"speleothem_mask\"", "\"scratch_words\": 2146",
                                      "\"name\": \"scratch\"", "\"speleothem_kind\": \"hoodoo\""})
        EXPECT_NE(manifest.find(expected), std::string::npos) << expected;
}

// The prepass is one dispatch over the whole grid, before the grid pass of the same stage.
TEST(caves_SpeleothemStage, PrepassRunsBeforeTheGridPass) {
    KernelPackage package = compileProgram(checked(slabSource("column", {0, 0, 0})), {});
    const StagePlan& stage = package.stages.at(1);
    std::vector<uint32_t> kernels;
    DispatchCursor cursor(package, {65535, 65535, 65535});
    for (Dispatch d; cursor.next(d);)
        if (d.stage == 1) kernels.push_back(d.kernel);
    EXPECT_EQ(kernels, (std::vector<uint32_t>{stage.prepassKernel, stage.gridKernel}));
    package.stages[1].gridKernel = kNoKernel; // a prepass with nothing to prepare for
    EXPECT_THROW(validatePackage(package), InternalError);
}

} // namespace
} // namespace voxc
