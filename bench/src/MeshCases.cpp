#include "MeshCases.h"

#include "voxc/check/Check.h"
#include "voxc/core/Errors.h"
#include "voxc/edit/EditableWorld.h"
#include "voxc/mesh/Lod.h"
#include "voxc/mesh/Export.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/mesh/MeshQuality.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/vulkan/Executor.h"
#include "voxc/vulkan/GpuMesher.h"

#include <fmt/format.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <glm/common.hpp>
#include <iostream>
#include <memory>
#include <thread>

namespace voxc::bench {

namespace {

constexpr int32_t kChunk = 32;
// lavapipe binds at most 128 MiB as one storage buffer, a 256^3 grid of floats; larger grids are
// made at 256^3 and resampled (see MeshInput::make).
constexpr int kLargestDeviceGrid = 256;

// `source` at `factor` times its resolution: densities trilinear between the source's voxels
// (output voxel p samples the source at p / factor, the last voxels clamped), materials from the
// nearest voxel. The same shapes with `factor` times more voxels per unit: factor^2 the surface
// and factor^3 the volume.
ChunkedGrid resample(const ChunkedGrid& source, int factor) {
    const DenseGrid dense = source.toDense();
    const glm::ivec3 size = dense.size() * factor;
    ChunkedGrid grid(ChunkLayout::make(glm::ivec3(0), size, kChunk));
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const glm::ivec3 p(x, y, z), lo = p / factor, hi = glm::min(lo + 1, dense.size() - 1);
                const glm::vec3 t = glm::vec3(p - lo * factor) / float(factor);
                auto at = [&](int cx, int cy, int cz) { return dense.at({cx ? hi.x : lo.x, cy ? hi.y : lo.y, cz ? hi.z : lo.z}); };
                auto lerp = [](float a, float b, float w) { return a + (b - a) * w; };
                const float d = lerp(lerp(lerp(at(0, 0, 0), at(1, 0, 0), t.x), lerp(at(0, 1, 0), at(1, 1, 0), t.x), t.y),
                                     lerp(lerp(at(0, 0, 1), at(1, 0, 1), t.x), lerp(at(0, 1, 1), at(1, 1, 1), t.x), t.y), t.z);
                grid.at(p) = d;
                grid.materialAt(p) = dense.materialAt(glm::min((p + factor / 2) / factor, dense.size() - 1));
            }
    grid.recordTileRanges(); // as the executor's read-back does for the grids it makes
    return grid;
}

// Every case meshes once untimed first (warm-up), then in the timed loop.
// One example's grid, made on first use and kept on the device (for the device mesher) and on
// the host (for the others).
struct MeshInput {
    std::string example;
    int n = 0;
    std::unique_ptr<VulkanExecutor> executor;
    std::unique_ptr<ChunkedGrid> grid;
    std::unique_ptr<GpuMarchingCubes> gpu;
    openvdb::FloatGrid::Ptr vdb;

    // Above kLargestDeviceGrid the example runs at that size and its grid is resampled to n^3
    // (n a multiple of it); the device mesher then has no n^3 grid on the device (not registered).
    void make(VulkanContext& context) {
        if (executor) return;
        CheckResult checked = checkFile(fmt::format("{}/examples/{}.vox", VOXC_SOURCE_DIR, example));
        if (!checked.program) throw UserError(checked.rendered());
        Program program = std::move(*checked.program);
        const int made = std::min(n, kLargestDeviceGrid);
        if (n % made != 0) throw UserError(fmt::format("mesh cases: n = {} is above {} and not a multiple of it", n, made));
        program.world.size = glm::ivec3(made);
        program.world.chunkSize = kChunk;
        executor = std::make_unique<VulkanExecutor>(context, compileProgram(program, {}));
        grid = std::make_unique<ChunkedGrid>(made == n ? executor->run().grid : resample(executor->run().grid, n / made));
    }

    // Densities negated, so that OpenVDB's inside (below the isovalue) is voxc's solid (above
    // iso); air (0) is the background, and constant regions are pruned into tiles, OpenVDB's own
    // representation of a volume. Built once, outside the timing.
    const openvdb::FloatGrid& vdbGrid(VulkanContext& context) {
        make(context);
        if (vdb) return *vdb;
        vdb = openvdb::FloatGrid::create(0.0f);
        openvdb::FloatGrid::Accessor access = vdb->getAccessor();
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const float d = grid->at({x, y, z});
                    if (d != 0.0f) access.setValue(openvdb::Coord(x, y, z), -d);
                }
        vdb->pruneGrid();
        return *vdb;
    }
};

void setCounters(benchmark::State& state, int n, size_t triangles) {
    const double voxels = double(n) * n * n;
    const double chunks = voxels / (double(kChunk) * kChunk * kChunk);
    state.counters["mvox_per_s"] = benchmark::Counter(voxels / 1e6, benchmark::Counter::kIsIterationInvariantRate);
    // Seconds per (chunks / 1000) = milliseconds per chunk.
    state.counters["ms_per_32_chunk"] =
        benchmark::Counter(chunks / 1000.0, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    state.counters["triangles"] = double(triangles);
}

std::string hostDescription() { return fmt::format("cpu ({} threads)", std::thread::hardware_concurrency()); }
// voxc's host meshers also name how they classify samples (AVX2 or scalar) on this CPU.
std::string hostMesherDescription() { return fmt::format("cpu ({} threads, {} classification)", std::thread::hardware_concurrency(), hostMeshSimd()); }

// edit_remesh: one brush on examples/scene.vox at 256^3, from the brush to the new mesh
// (EditableWorld::edit: the brush, its diff and the chunks R2 names; then mesh(): the grid meshed
// again, uniform tiles skipped). The brush sits on the surface under the grid's centre, found by a
// pick; iterations alternate carve and add at the same place, so every one changes voxels and the
// world does not drift. "edit_remesh_chunk16": the same grid re-chunked to 16^3.
void registerEditCases(JsonReporter& reporter, VulkanContext& context) {
    constexpr int n = 256;
    auto input = std::make_shared<MeshInput>();
    input->example = "scene";
    input->n = n;
    for (int32_t chunk : {kChunk, 16})
    for (float radius : {4.0f, 8.0f, 16.0f}) {
        const std::string caseName = chunk == kChunk ? "edit_remesh" : fmt::format("edit_remesh_chunk{}", chunk);
        const std::string name = fmt::format("{}/{}/host", caseName, int(radius));
        benchmark::RegisterBenchmark(name.c_str(), [input, &context, radius, chunk](benchmark::State& state) {
            input->make(context);
            const ChunkLayout& layout = input->grid->layout();
            EditableWorld world(chunk == layout.chunkSize
                                    ? *input->grid
                                    : ChunkedGrid::fromDense(input->grid->toDense(),
                                                             ChunkLayout::make(layout.gridOrigin, layout.gridSize, chunk)));
            const std::optional<PickHit> hit = world.pick({n / 2.0f, float(n) + 1.0f, n / 2.0f}, {0.0f, -1.0f, 0.0f});
            if (!hit) throw InternalError("edit_remesh: the pick from above the scene found no surface");
            Brush brush{Brush::Op::Carve, hit->point, radius, 2.0f};
            size_t chunks = world.edit(brush).chunksRemeshed.size(); // warm-up
            size_t triangles = world.mesh().triangles.size() / 3;
            for (auto _ : state) {
                brush.op = brush.op == Brush::Op::Carve ? Brush::Op::Add : Brush::Op::Carve;
                chunks = world.edit(brush).chunksRemeshed.size();
                triangles = world.mesh().triangles.size() / 3;
            }
            state.counters["chunks_remeshed"] = double(chunks);
            state.counters["triangles"] = double(triangles);
        })->Unit(benchmark::kMillisecond)->UseRealTime();
        reporter.describe(name + "/real_time", {caseName, int(radius), "host", hostDescription()});
    }
}

} // namespace

void registerMeshCases(JsonReporter& reporter, VulkanContext& context, const std::vector<int>& sizes, bool host,
                       bool vulkan, bool openvdb) {
    openvdb::initialize();
    for (const char* example : {"terrain", "scene"})
        for (int n : sizes) {
            auto input = std::make_shared<MeshInput>();
            input->example = example;
            input->n = n;
            const std::string mc = fmt::format("mesh_mc_{}", example), sn = fmt::format("mesh_sn_{}", example);
            auto add = [&](const std::string& caseName, const std::string& backend, const std::string& device, auto body) {
                const std::string name = fmt::format("{}/{}/{}", caseName, n, backend);
                benchmark::RegisterBenchmark(name.c_str(), body)->Unit(benchmark::kMillisecond)->UseRealTime();
                reporter.describe(name + "/real_time", {caseName, n, backend, device});
            };
            if (host) {
                add(mc, "host", hostMesherDescription(), [input, &context](benchmark::State& state) {
                    input->make(context);
                    MeshStats stats;
                    size_t triangles = meshMarchingCubes(*input->grid, {}).triangles.size() / 3; // warm-up
                    double normalsMs = 0.0;
                    for (auto _ : state) {
                        triangles = meshMarchingCubes(*input->grid, {}, &stats).triangles.size() / 3;
                        normalsMs += stats.normalsMs;
                    }
                    setCounters(state, input->n, triangles);
                    // The part of the time spent orienting the normals (voxc run --timings: normals).
                    state.counters["normals_ms"] = normalsMs / double(std::max<benchmark::IterationCount>(1, state.iterations()));
                });
                // The executor's read-back of the grid with its tile ranges (loadDensities, which
                // the host mesher's case reads), against a plain copy of the same bytes.
                add(fmt::format("mesh_tile_ranges_{}", example), "host", hostDescription(), [input, &context](benchmark::State& state) {
                    input->make(context);
                    ChunkedGrid target(input->grid->layout());
                    const float* source = input->grid->data().data();
                    target.loadDensities(source); // warm-up: the target's pages
                    for (auto _ : state) target.loadDensities(source);
                    double copyMs = 1e300;
                    for (int i = 0; i < 3; ++i) {
                        const auto start = std::chrono::steady_clock::now();
                        std::memcpy(target.data().data(), source, input->grid->data().size() * sizeof(float));
                        copyMs = std::min(copyMs, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
                    }
                    state.counters["memcpy_ms"] = copyMs;
                    setCounters(state, input->n, 0);
                });
                // Levels 0-2 around a corner of the grid, transition cells where they meet; the
                // pyramid is made once, outside the timing (it changes only with the voxels).
                add(fmt::format("mesh_lod_{}", example), "host", hostDescription(), [input, &context](benchmark::State& state) {
                    input->make(context);
                    const LodPyramid pyramid(*input->grid, 2);
                    const LodLayout layout = LodLayout::aroundPoint(input->grid->layout(), glm::vec3(0.0f, float(input->n) / 2, 0.0f), 2);
                    size_t triangles = meshLod(pyramid, layout, {}).triangles.size() / 3; // warm-up
                    for (auto _ : state) triangles = meshLod(pyramid, layout, {}).triangles.size() / 3;
                    setCounters(state, input->n, triangles);
                });
                // What `voxc run` does with the mesh after extracting it: the quality report it
                // prints, and the .glb (meshoptimizer's vertex cache and fetch order, encoding);
                // the marching-cubes mesh is made once, outside the timing.
                add(fmt::format("mesh_quality_{}", example), "host", hostDescription(), [input, &context](benchmark::State& state) {
                    input->make(context);
                    const Mesh mesh = meshMarchingCubes(*input->grid, {});
                    size_t edges = measureMeshQuality(mesh).boundaryEdges; // warm-up
                    for (auto _ : state) edges += measureMeshQuality(mesh).boundaryEdges;
                    if (edges != 0) throw InternalError("mesh_quality: the marching-cubes mesh has boundary edges");
                    setCounters(state, input->n, mesh.triangles.size() / 3);
                });
                add(fmt::format("mesh_glb_{}", example), "host", hostDescription(), [input, &context](benchmark::State& state) {
                    input->make(context);
                    const Mesh mesh = meshMarchingCubes(*input->grid, {});
                    size_t bytes = encodeGlb(mesh).size(); // warm-up
                    for (auto _ : state) bytes = encodeGlb(mesh).size();
                    state.counters["bytes"] = double(bytes);
                    setCounters(state, input->n, mesh.triangles.size() / 3);
                });
                add(sn, "host", hostDescription(), [input, &context](benchmark::State& state) {
                    input->make(context);
                    size_t triangles = meshSurfaceNets(*input->grid, {}).triangles.size() / 3; // warm-up
                    for (auto _ : state) triangles = meshSurfaceNets(*input->grid, {}).triangles.size() / 3;
                    setCounters(state, input->n, triangles);
                });
            }
            if (vulkan && n <= kLargestDeviceGrid)
                add(mc, "vulkan", context.device().name, [input, &context](benchmark::State& state) {
                    input->make(context);
                    if (!input->gpu) input->gpu = std::make_unique<GpuMarchingCubes>(*input->executor);
                    size_t triangles = input->gpu->mesh({}).triangles.size() / 3; // warm-up: output buffers
                    for (auto _ : state) triangles = input->gpu->mesh({}).triangles.size() / 3;
                    setCounters(state, input->n, triangles);
                });
            if (openvdb)
                add(mc, "openvdb", fmt::format("openvdb {} volumeToMesh, {}", OPENVDB_LIBRARY_VERSION_STRING, hostDescription()),
                    [input, &context](benchmark::State& state) {
                        const openvdb::FloatGrid& grid = input->vdbGrid(context);
                        auto mesh = [&grid] {
                            std::vector<openvdb::Vec3s> points;
                            std::vector<openvdb::Vec4I> quads;
                            openvdb::tools::volumeToMesh(grid, points, quads, -0.5);
                            return quads.size() * 2;
                        };
                        size_t triangles = mesh(); // warm-up
                        for (auto _ : state) triangles = mesh();
                        setCounters(state, input->n, triangles);
                    });
        }
    if (host) registerEditCases(reporter, context);
}

} // namespace voxc::bench
