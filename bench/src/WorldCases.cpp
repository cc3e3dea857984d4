#include "WorldCases.h"

#include "voxc/check/Check.h"
#include "voxc/core/Errors.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/vulkan/Executor.h"
#include "voxc/world/Tiles.h"

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <unistd.h>

namespace voxc::bench {

namespace {

namespace fs = std::filesystem;

// scene.vox with `size = [n, 64, n]`: its terrain, arch, cave and grammar pass over a larger area.
Program sceneWorld(int n, int32_t tile) {
    const std::string path = fmt::format("{}/examples/scene.vox", VOXC_SOURCE_DIR);
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    std::string source = std::move(text).str();
    const std::string declared = "size = [96, 64, 96];";
    const size_t at = source.find(declared);
    if (at == std::string::npos) throw InternalError("the world bench expects scene.vox to declare " + declared);
    source.replace(at, declared.size(), fmt::format("size = [{}, 64, {}];", n, n));
    CheckOptions options;
    options.region = std::pair(glm::ivec3(0), glm::ivec3(tile, 64, tile)); // checked as its tiles run
    CheckResult checked = checkSource(SourceFile(path, source), options);
    if (!checked.program) throw InternalError("the world bench's scene does not check:\n" + checked.rendered());
    return std::move(*checked.program);
}

} // namespace

void registerWorldCases(JsonReporter& reporter, VulkanContext& context) {
    for (const auto& [n, tile] : {std::pair(256, 64), std::pair(512, 256)}) {
        auto program = std::make_shared<const Program>(sceneWorld(n, tile));
        const std::string caseName = fmt::format("world_tile{}", tile);
        const std::string name = fmt::format("{}/{}", caseName, n);
        benchmark::RegisterBenchmark(name.c_str(), [program, &context, n, tile](benchmark::State& state) {
            const fs::path directory = fs::temp_directory_path() / fmt::format("voxc_bench_world_{}_{}_{}", ::getpid(), n, tile);
            world::WorldOptions options;
            options.directory = directory.string();
            options.tile = tile;
            options.sourceText = "bench";
            world::WorldSummary summary;
            for (auto _ : state) {
                fs::remove_all(directory);
                // A context per run, sharing the tiles' pipelines as `voxc world`'s does, so every
                // run compiles its kernels once as a first `voxc world` does.
                VulkanContext device(ContextOptions{.device = std::to_string(context.device().index),
                                                    .shareKernelPipelines = true});
                options.run = [&device](const Program& region) {
                    VulkanExecutor executor(device, compileProgram(region, {}));
                    return executor.run().grid.toDense();
                };
                summary = world::writeWorld(*program, options);
            }
            fs::remove_all(directory);
            state.counters["tiles_per_second"] = benchmark::Counter(double(summary.tiles), benchmark::Counter::kIsIterationInvariantRate);
            state.counters["voxels_per_second"] =
                benchmark::Counter(double(summary.voxelsWritten), benchmark::Counter::kIsIterationInvariantRate);
            state.counters["halo_overhead"] = double(summary.voxelsComputed) / double(summary.voxelsWritten);
        })->Unit(benchmark::kMillisecond)->UseRealTime();
        reporter.describe(name + "/real_time", {caseName, n, "vulkan", context.device().name});
    }
}

} // namespace voxc::bench
