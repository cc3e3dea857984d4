#include "InputCases.h"

#include "voxc/check/Check.h"
#include "voxc/core/Errors.h"
#include "voxc/generators/inputs/MeshDistance.h"

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <cstdint>
#include <fstream>
#include <memory>
#include <numbers>

namespace voxc::bench {
namespace {

constexpr int kMapSide = 4096;

// The .npy v1.0 header of a (side, side) little-endian float32 array, padded to 64 bytes.
std::string npyHeader(int side) {
    std::string dict = fmt::format("{{'descr': '<f4', 'fortran_order': False, 'shape': ({}, {}), }}", side, side);
    const size_t unpadded = 10 + dict.size() + 1;
    dict.append((64 - unpadded % 64) % 64, ' ');
    dict += '\n';
    std::string header("\x93NUMPY\x01\x00", 8);
    header += char(dict.size() & 0xff);
    header += char(dict.size() >> 8);
    return header + dict;
}

void writeReliefNpy(const std::string& path) {
    std::vector<float> heights(size_t(kMapSide) * kMapSide);
    for (int z = 0; z < kMapSide; ++z)
        for (int x = 0; x < kMapSide; ++x) {
            const double u = double(x) / kMapSide, v = double(z) / kMapSide;
            heights[size_t(z) * kMapSide + x] =
                float(0.5 + 0.25 * std::sin(9.0 * u) * std::cos(7.0 * v) + 0.1 * std::sin(40.0 * (u + v)));
        }
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    const std::string header = npyHeader(kMapSide);
    out.write(header.data(), std::streamsize(header.size()));
    out.write(reinterpret_cast<const char*>(heights.data()), std::streamsize(heights.size() * sizeof(float)));
    if (!out) throw InternalError("cannot write the heightmap bench's map " + path);
}

// A latitude-longitude sphere: `rings` x `segments` quads, each two triangles (the poles' fans
// included), so 2 * rings * segments triangles.
inputs::TriangleMesh sphereMesh(double radius, int rings, int segments) {
    inputs::TriangleMesh mesh;
    mesh.points.push_back({0, radius, 0});
    for (int r = 1; r < rings; ++r) {
        const double theta = std::numbers::pi * r / rings;
        for (int s = 0; s < segments; ++s) {
            const double phi = 2 * std::numbers::pi * s / segments;
            mesh.points.push_back({radius * std::sin(theta) * std::cos(phi), radius * std::cos(theta),
                                   radius * std::sin(theta) * std::sin(phi)});
        }
    }
    mesh.points.push_back({0, -radius, 0});
    const auto ring = [&](int r, int s) { return uint32_t(1 + (r - 1) * segments + (s % segments)); };
    const uint32_t south = uint32_t(mesh.points.size() - 1);
    for (int s = 0; s < segments; ++s) {
        mesh.triangles.push_back({0, ring(1, s + 1), ring(1, s)});
        mesh.triangles.push_back({south, ring(rings - 1, s), ring(rings - 1, s + 1)});
        for (int r = 1; r + 1 < rings; ++r) {
            mesh.triangles.push_back({ring(r, s), ring(r, s + 1), ring(r + 1, s)});
            mesh.triangles.push_back({ring(r + 1, s), ring(r, s + 1), ring(r + 1, s + 1)});
        }
    }
    return mesh;
}

} // namespace

Program heightmapProgram() {
    // The map is read when the program is checked, so the directory goes right after.
    std::string directory = (std::filesystem::temp_directory_path() / "voxc-bench-XXXXXX").string();
    if (!::mkdtemp(directory.data())) throw InternalError("cannot make a temporary directory for the heightmap bench");
    struct RemoveAfter {
        std::string path;
        ~RemoveAfter() { std::filesystem::remove_all(path); }
    } removeAfter{directory};
    writeReliefNpy(directory + "/relief.npy");
    const std::string text = R"(world { size = [512, 128, 512]; chunk = 32; seed = 1; }
heightmap relief { file = "relief.npy"; size = [512, 512]; height = [8, 120]; values = [0, 1]; }
field ground = clamp(relief(wx, wz) - wy + 0.5, 0, 1);
pipeline { start; set ground; }
)";
    CheckResult result = checkSource(SourceFile(directory + "/heightmap.vox", text));
    if (result.hasErrors() || !result.program)
        throw InternalError("the heightmap bench program does not check:\n" + result.rendered());
    return std::move(*result.program);
}

void registerMeshSdf(JsonReporter& reporter) {
    auto mesh = std::make_shared<const inputs::TriangleMesh>(sphereMesh(110.0, 224, 224));
    const inputs::MeshTransform transform{.translate = glm::dvec3(128.0)};
    const std::string name = "mesh_sdf/256/host";
    auto warmedUp = std::make_shared<bool>(false);
    benchmark::RegisterBenchmark(name.c_str(), [mesh, transform, warmedUp](benchmark::State& state) {
        if (!*warmedUp) benchmark::DoNotOptimize(inputs::meshDistances(*mesh, transform, 3.0f).values.data());
        *warmedUp = true;
        for (auto _ : state) benchmark::DoNotOptimize(inputs::meshDistances(*mesh, transform, 3.0f).values.data());
        state.counters["triangles"] = double(mesh->triangles.size());
    })->Unit(benchmark::kMillisecond);
    reporter.describe(name, {"mesh_sdf", 256, "host", "cpu (OpenVDB meshToVolume, TBB threads)"});
}

} // namespace voxc::bench
