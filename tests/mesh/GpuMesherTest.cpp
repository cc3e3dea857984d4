// Marching cubes on the device (voxc/vulkan/GpuMesher.h) against the CPU mesher, its oracle: on
// lavapipe the index buffer, materials, skipped-chunk and active-tile counts are identical and
// positions and normals bit-identical, for several examples, chunk sizes and origins that are not
// multiples of the chunk size or of the 8^3 tiles, with and without skipping, under the
// validation layer.
#include "voxc/check/Check.h"
#include "voxc/core/Errors.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/mesh/MeshQuality.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/syntax/SourceFile.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"
#include "voxc/vulkan/GpuMesher.h"

#include <cstring>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace voxc {
namespace {

VulkanContext& validatedLavapipe() {
    static VulkanContext context(ContextOptions{.device = "lavapipe", .validation = true});
    return context;
}

Program example(const std::string& name, int32_t chunkSize, glm::ivec3 origin, glm::ivec3 size = glm::ivec3(0)) {
    CheckResult result = checkFile(fmt::format("{}/examples/{}", VOXC_SOURCE_DIR, name));
    EXPECT_TRUE(result.program) << result.rendered();
    Program program = std::move(*result.program);
    program.world.chunkSize = chunkSize;
    program.world.origin = origin;
    if (size != glm::ivec3(0)) program.world.size = size;
    return program;
}

template <typename T>
size_t countBitDifferences(const std::vector<T>& expected, const std::vector<T>& actual, const std::string& what) {
    EXPECT_EQ(expected.size(), actual.size()) << what;
    size_t differences = 0;
    for (size_t i = 0; i < std::min(expected.size(), actual.size()); ++i)
        if (std::memcmp(&expected[i], &actual[i], sizeof(T)) != 0 && differences++ < 3)
            ADD_FAILURE() << what << " " << i << " differs";
    return differences;
}

void expectSameMesh(const Mesh& cpu, const Mesh& gpu, const std::string& what) {
    EXPECT_EQ(countBitDifferences(cpu.positions, gpu.positions, what + ": position"), 0u);
    EXPECT_EQ(countBitDifferences(cpu.normals, gpu.normals, what + ": normal"), 0u);
    EXPECT_EQ(cpu.triangles, gpu.triangles) << what;
    EXPECT_EQ(cpu.vertexMaterials, gpu.vertexMaterials) << what;
    EXPECT_EQ(cpu.triangleMaterials, gpu.triangleMaterials) << what;
    EXPECT_EQ(cpu.normalSplits, gpu.normalSplits) << what;
}

void expectNoValidationMessages(VulkanContext& context) {
    for (const ValidationMessage& m : context.validationMessages())
        ADD_FAILURE() << (m.error ? "validation error: " : "validation warning: ") << m.text;
    context.clearValidationMessages();
}

struct Case {
    const char* file;
    int32_t chunkSize;
    glm::ivec3 origin;
};

// Materials (scene), a grammar over noise (terrain), a grammar's saddles (overhang, cave_grammar),
// field CSG (fields); chunk sizes 8 to 64; origins negative, odd and past 2^10 (a wider margin).
const Case kCases[] = {
    {"scene.vox", 32, {-37, -5, -70}}, {"terrain.vox", 16, {0, 0, 0}},       {"overhang.vox", 8, {3, -9, 5}},
    {"cave_grammar.vox", 16, {1000, 17, -999}}, {"fields.vox", 64, {-64, 1, 13}},
};

TEST(mesh_GpuMarchingCubes, MatchesTheCpuMesherBitForBit) {
    VulkanContext& context = validatedLavapipe();
    for (const Case& c : kCases) {
        const Program program = example(c.file, c.chunkSize, c.origin);
        VulkanExecutor executor(context, compileProgram(program, {}));
        const RunResult result = executor.run();
        GpuMarchingCubes gpu(executor);
        for (const float iso : {0.5f, 0.3f})
            for (const bool skip : {true, false}) {
                const std::string what = fmt::format("{} chunk {} iso {} skip {}", c.file, c.chunkSize, iso, skip);
                const MeshOptions options{.iso = iso, .skipUniformChunks = skip};
                MeshStats cpuStats, gpuStats;
                const Mesh cpu = meshMarchingCubes(result.grid, options, &cpuStats);
                const Mesh gpuMesh = gpu.mesh(options, &gpuStats);
                ASSERT_GT(cpu.triangles.size(), 0u) << what;
                expectSameMesh(cpu, gpuMesh, what);
                EXPECT_EQ(gpuStats.chunks, cpuStats.chunks) << what;
                EXPECT_EQ(gpuStats.skippedChunks, cpuStats.skippedChunks) << what;
                EXPECT_EQ(gpuStats.tiles, cpuStats.tiles) << what;
                EXPECT_EQ(gpuStats.activeTiles, cpuStats.activeTiles) << what;
                // Only the crossed tiles' cells are counted (every tile's without skipping).
                if (skip) {
                    EXPECT_LT(gpuStats.activeTiles, gpuStats.tiles) << what;
                    EXPECT_LE(gpuStats.cellsVisited, gpuStats.activeTiles * 512) << what;
                } else {
                    EXPECT_EQ(gpuStats.cellsVisited, cpuStats.cellsVisited) << what;
                }
                if (skip && iso == 0.5f) {
                    EXPECT_GT(gpuStats.skippedChunks, 0u) << what;
                }
                EXPECT_TRUE(measureMeshQuality(gpuMesh).manifold()) << what;
            }
        expectNoValidationMessages(context);
    }
}

// Where the executor's materials are not mapped (staged, as on a discrete GPU), the device votes
// the triangles' materials (mc_materials.glsl) where the host does elsewhere: the same mesh.
TEST(mesh_GpuMarchingCubes, VotesMaterialsOnTheDeviceWhereTheyAreStaged) {
    VulkanContext& context = validatedLavapipe();
    const Program program = example("scene.vox", 32, {-37, -5, -70});
    VulkanExecutor executor(context, compileProgram(program, {}), {.alwaysStage = true});
    const RunResult result = executor.run();
    GpuMarchingCubes gpu(executor);
    const Mesh cpu = meshMarchingCubes(result.grid, {});
    ASSERT_GT(cpu.triangles.size(), 0u);
    expectSameMesh(cpu, gpu.mesh({}), "staged");
    expectNoValidationMessages(context);
}

// A surface inside one world-aligned 8^3 tile (the host test mesh_MarchingCubes.
// surfaceInOneTileVisitsOnlyThatTile's ball): the device counts the 512 cells of that tile alone,
// no other (its count pass and the host's lists run over the segments of the active tiles), and
// meshes them as the host does; with the executor's tile ranges and without them (no read-back,
// as `voxc run --mesh-on device` runs), where the tiles pass reads every tile's voxels.
TEST(mesh_GpuMarchingCubes, ASurfaceInOneTileIsCountedInThatTileAlone) {
    VulkanContext& context = validatedLavapipe();
    const std::string text = "world {\n  size = [64, 64, 64];\n  seed = 1;\n}\n"
                             "field ball = max(0.0, 1.0 - length(wp - vec3(11.5, 11.5, 11.5)) / 3.6);\n"
                             "pipeline {\n  start;\n  set ball;\n}\n";
    for (const glm::ivec3 origin : {glm::ivec3(0), glm::ivec3(-40, 8, 3)})
    for (const bool readBack : {true, false}) {
        CheckResult checked = checkSource(SourceFile("ball.vox", text));
        ASSERT_TRUE(checked.program) << checked.rendered();
        Program program = std::move(*checked.program);
        program.world.chunkSize = 32;
        program.world.origin = origin;
        // The host mesher's grid comes from an executor that reads it back.
        VulkanExecutor host(context, compileProgram(program, {}));
        const RunResult result = host.run();
        VulkanExecutor executor(context, compileProgram(program, {}), {.readBack = readBack});
        executor.run();
        GpuMarchingCubes gpu(executor);
        MeshStats cpuStats, gpuStats;
        const Mesh cpu = meshMarchingCubes(result.grid, {}, &cpuStats);
        const Mesh gpuMesh = gpu.mesh({}, &gpuStats);
        const std::string what = fmt::format("origin {} {} {} read back {}", origin.x, origin.y, origin.z, readBack);
        ASSERT_EQ(cpuStats.activeTiles, 1u) << what;
        expectSameMesh(cpu, gpuMesh, what);
        EXPECT_GT(gpuMesh.triangles.size(), 0u) << what;
        EXPECT_EQ(gpuStats.activeTiles, 1u) << what;
        EXPECT_EQ(gpuStats.cellsVisited, 512u) << what;
        EXPECT_EQ(gpuStats.tiles, cpuStats.tiles) << what;
        EXPECT_EQ(gpuStats.skippedChunks, gpuStats.chunks - 1) << what;
    }
    expectNoValidationMessages(context);
}

TEST(mesh_GpuMarchingCubes, IsTheSameForEveryChunkSizeAndRepeatedCall) {
    VulkanContext& context = validatedLavapipe();
    std::vector<Mesh> meshes;
    // Read back, the run leaves the tile ranges that settle the uniform tiles without the tiles
    // pass reading them; without a read-back the tiles pass reads every tile.
    for (const int32_t chunk : {8, 32})
        for (const bool readBack : {true, false}) {
            VulkanExecutor executor(context, compileProgram(example("overhang.vox", chunk, {-5, 2, -11}), {}), {.readBack = readBack});
            executor.run();
            GpuMarchingCubes gpu(executor);
            meshes.push_back(gpu.mesh({}));
            meshes.push_back(gpu.mesh({})); // the buffers of the first call are reused
        }
    for (size_t i = 1; i < meshes.size(); ++i) expectSameMesh(meshes[0], meshes[i], fmt::format("mesh {}", i));
    expectNoValidationMessages(context);
}

// The count pass runs an invocation per row of cells of the active tiles, and the host lists the
// active cells from those rows: a grid of fewer than 1024 cells has a few rows in one workgroup,
// partly outside the grid; a 110 x 99 x 110 grid meshed without skipping has 15 x 13 x 15 tiles
// and 100 x 111 rows of them, 166,500 rows in 2,602 workgroups.
TEST(mesh_GpuMarchingCubes, MatchesTheCpuMesherFromATinyGridToALargeOne) {
    VulkanContext& context = validatedLavapipe();
    for (const glm::ivec3 size : {glm::ivec3(9, 8, 7), glm::ivec3(110, 99, 110)}) {
        VulkanExecutor executor(context, compileProgram(example("fields.vox", 16, {-3, 20, 5}, size), {}));
        const RunResult result = executor.run();
        GpuMarchingCubes gpu(executor);
        const float iso = size.x < 16 ? 0.0f : 0.5f; // the small box: whatever is not air
        for (const bool skip : {true, false}) {
            const std::string what = fmt::format("{}x{}x{} skip {}", size.x, size.y, size.z, skip);
            const Mesh cpu = meshMarchingCubes(result.grid, {.iso = iso, .skipUniformChunks = skip});
            ASSERT_GT(cpu.triangles.size(), 0u) << what;
            expectSameMesh(cpu, gpu.mesh({.iso = iso, .skipUniformChunks = skip}), what);
        }
    }
    expectNoValidationMessages(context);
}

// Without the layer, which wraps handles, lavapipe can give a new buffer the handle value of the
// one it replaces; the mesher must still point its descriptors at the new one.
TEST(mesh_GpuMarchingCubes, MatchesTheCpuMesherWithoutTheValidationLayer) {
    static VulkanContext context(ContextOptions{.device = "lavapipe"});
    for (const int32_t chunk : {32, 8}) {
        VulkanExecutor executor(context, compileProgram(example("overhang.vox", chunk, {0, 0, 0}), {}));
        const RunResult result = executor.run();
        GpuMarchingCubes gpu(executor);
        const Mesh small = gpu.mesh({.iso = 0.9f}); // then larger output buffers replace the first ones
        expectSameMesh(meshMarchingCubes(result.grid, {.iso = 0.9f}), small, fmt::format("chunk {} iso 0.9", chunk));
        expectSameMesh(meshMarchingCubes(result.grid, {}), gpu.mesh({}), fmt::format("chunk {}", chunk));
    }
}

TEST(mesh_GpuMarchingCubes, AGridWithNoSurfaceGivesAnEmptyMesh) {
    VulkanContext& context = validatedLavapipe();
    VulkanExecutor executor(context, compileProgram(example("terrain.vox", 16, {0, 0, 0}), {}));
    executor.run();
    GpuMarchingCubes gpu(executor);
    MeshStats stats;
    const Mesh mesh = gpu.mesh({.iso = 2.0f}, &stats); // no density exceeds 2: all air
    EXPECT_TRUE(mesh.positions.empty());
    EXPECT_TRUE(mesh.triangles.empty());
    EXPECT_EQ(stats.skippedChunks, stats.chunks);
    EXPECT_GT(stats.chunks, 0u);
    expectNoValidationMessages(context);
}

TEST(mesh_GpuMarchingCubes, MeshingBeforeAnyRunIsAnInternalError) {
    VulkanExecutor executor(validatedLavapipe(), compileProgram(example("terrain.vox", 16, {0, 0, 0}), {}));
    GpuMarchingCubes gpu(executor);
    EXPECT_THROW(gpu.mesh({}), InternalError);
}

} // namespace
} // namespace voxc
