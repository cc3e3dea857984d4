// erosion: CPU speed of the terrain core's pipe-model erosion step (docs/terrain.md) on a 512^2
// grid of hills with the mountain_river preset; reports cell-steps per second, to set against the
// thesis's ~130 M cell-steps/s on an RTX 2060 Super (spec B5).
#include "TerrainCases.h"

#include "voxc/generators/terrain/Erosion.h"

#include <cmath>

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

} // namespace

void registerErosion(JsonReporter& reporter) {
    const std::string name = "erosion";
    benchmark::RegisterBenchmark(name.c_str(), [](benchmark::State& state) {
        const terrain::ErosionParams params = terrain::findPreset("mountain_river")->params;
        terrain::ErosionGrid grid = hills();
        uint32_t step = 0;
        for (auto _ : state)
            for (uint32_t k = 0; k < kStepsPerIteration; ++k) terrain::erosionStep(grid, params, 9, step++);
        benchmark::DoNotOptimize(grid.water.values.data());
        state.counters["cell_steps_per_second"] =
            benchmark::Counter(double(kSide) * kSide * kStepsPerIteration, benchmark::Counter::kIsIterationInvariantRate);
    })->Unit(benchmark::kMillisecond)->UseRealTime();
    reporter.describe(name + "/real_time", {"erosion", kSide, "host", "cpu (1 thread)"});
}

} // namespace voxc::bench
