// erosion: CPU speed of the terrain core's pipe-model erosion step (docs/terrain.md) on a 512^2
// grid of hills with the mountain_river preset; reports cell-steps per second, to set against the
// thesis's ~130 M cell-steps/s on an RTX 2060 Super (spec B5).
// terrain_mountain_river: generateTerrain end to end (rasterisation, cascade, noise, the preset's
// erosion schedule truncated at the map's finest level, drain), to set against Table 5.4.
#include "TerrainCases.h"

#include "voxc/generators/terrain/Erosion.h"
#include "voxc/generators/terrain/Terrain.h"
#include "voxc/vulkan/GpuErosion.h"

#include <sys/resource.h>

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <utility>

namespace voxc::bench {

namespace {

constexpr int32_t kSide = 512;
constexpr uint32_t kStepsPerIteration = 10;

terrain::ErosionGrid hills() {
    terrain::ErosionGrid grid(kSide, kSide);
    for (int32_t y = 0; y < kSide; ++y)
        for (int32_t x = 0; x < kSide; ++x)
            grid.base.at(x, y) = float(0.5 + 0.25 * std::sin(x * 0.031) * std::cos(y * 0.023) + 0.1 * std::sin((x + y) * 0.11));
    return grid;
}

// examples/valley.vox's two ridges and river scaled to a side x side domain (its finest level one
// cell per voxel), with the mountain_river preset's steps on the levels up to that one.
terrain::TerrainMap valleyMap(int32_t side) {
    terrain::TerrainMap map;
    const double k = side / 128.0;
    map.domain.size = side;
    map.domain.minLevel = 2;
    map.domain.maxLevel = std::bit_width(uint32_t(side)) - 1;
    map.domain.maxHeight = 40.0 * k;
    map.noise.amplitude = 6.0 * k;
    map.noise.scale = 3.0;
    const auto spline = [&](std::vector<glm::dvec3> points, double radius, double band, double rise, double rain) {
        terrain::Spline s;
        for (glm::dvec3& p : points) s.controlPoints.push_back(p * k);
        terrain::MetaPoint meta;
        meta.radius = radius * k;
        meta.left = meta.right = glm::dvec2(band, rise) * k;
        meta.hardness = 0.15;
        meta.rain = rain;
        s.metaPoints = {meta};
        s.minLevel = map.domain.minLevel;
        s.maxLevel = map.domain.maxLevel;
        map.splines.push_back(std::move(s));
    };
    spline({{0, 34, 20}, {40, 36, 16}, {88, 36, 24}, {128, 34, 20}}, 6, 30, -24, 1);
    spline({{0, 30, 110}, {40, 32, 108}, {88, 30, 112}, {128, 30, 108}}, 5, 28, -20, 1);
    spline({{0, 8, 64}, {40, 8, 80}, {88, 8, 48}, {128, 8, 64}}, 3, 24, 14, 2);
    return map;
}

double peakRssMiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_maxrss) / 1024.0;
}

} // namespace

void registerTerrainSchedule(JsonReporter& reporter, const std::vector<int>& sides, bool host, VulkanContext* device) {
    std::vector<VulkanContext*> backends; // nullptr: the host
    if (host) backends.push_back(nullptr);
    if (device) backends.push_back(device);
    for (const int side : sides)
        for (VulkanContext* context : backends) {
            const std::string backend = context ? "vulkan" : "host";
            const std::string name = fmt::format("terrain_mountain_river/{}/{}", side, backend);
            benchmark::RegisterBenchmark(name.c_str(), [side, context](benchmark::State& state) {
                const terrain::TerrainMap map = valleyMap(side);
                terrain::ErosionSettings erosion = terrain::presetSettings("mountain_river");
                if (context) erosion.runner = vulkanErosionRunner(*context);
                std::erase_if(erosion.levelSteps, [&](const auto& entry) { return entry.first > map.domain.maxLevel; });
                uint64_t cellSteps = 0;
                for (auto _ : state) {
                    const terrain::TerrainResult result = terrain::generateTerrain(map, erosion);
                    cellSteps = result.erosionCellSteps;
                    benchmark::DoNotOptimize(result.height.values.data());
                }
                state.counters["erosion_cell_steps"] = double(cellSteps);
                state.counters["cell_steps_per_second"] =
                    benchmark::Counter(double(cellSteps), benchmark::Counter::kIsIterationInvariantRate);
                state.counters["peak_rss_mib"] = peakRssMiB();
            })->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
            reporter.describe(name + "/iterations:1/real_time",
                              {"terrain_mountain_river", side, backend,
                               context ? context->device().name + " (erosion steps)" : "cpu (2 threads)"});
        }
}

void registerErosion(JsonReporter& reporter) {
    const std::string name = "erosion";
    benchmark::RegisterBenchmark(name.c_str(), [](benchmark::State& state) {
        const terrain::ErosionParams params = terrain::findPreset("mountain_river")->params;
        terrain::ErosionGrid grid = hills();
        uint32_t step = 0;
        for (auto _ : state)
            terrain::erosionSteps(grid, params, 9, std::exchange(step, step + kStepsPerIteration), kStepsPerIteration, false);
        benchmark::DoNotOptimize(grid.water.values.data());
        state.counters["cell_steps_per_second"] =
            benchmark::Counter(double(kSide) * kSide * kStepsPerIteration, benchmark::Counter::kIsIterationInvariantRate);
    })->Unit(benchmark::kMillisecond)->UseRealTime();
    reporter.describe(name + "/real_time", {"erosion", kSide, "host", "cpu (2 threads)"});
}

} // namespace voxc::bench
