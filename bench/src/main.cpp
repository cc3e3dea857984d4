// voxc-bench: times the grammar cases and a 5-octave fBm field on the Vulkan path and in the
// interpreter, the same fBm with libnoise as a peer, on the host the L-system expansion and
// codegen of the largest grammars the limits allow, and meshing (marching cubes on the host and
// the device, surface nets, OpenVDB's volumeToMesh as a peer).
// `voxc-bench --json` prints a JSON list of records; without it Google Benchmark's table.
// Vulkan times cover execution and readback of an already-built package, after one untimed run
// (the driver's JIT compiles a pipeline at its first dispatch); the package's codegen and pipeline
// creation is its own record (backend "vulkan_setup"). Interpreter times cover the same work:
// start state plus one grammar iteration, or the field, also after one untimed run.
// `--repetitions N` (default 3) repeats every case and records the median and the spread.
#include "Cases.h"
#include "CompileCases.h"
#include "LspCases.h"
#include "JsonReporter.h"
#include "CarveCases.h"
#include "SpeleothemCases.h"
#include "CurvesCases.h"
#include "InputCases.h"
#include "LsystemCases.h"
#include "MeshCases.h"
#include "TerrainCases.h"
#include "ViewCases.h"
#include "WorldCases.h"

#include "voxc/stages/Pipeline.h"
#include "voxc/core/Errors.h"
#include "voxc/interp/FieldEval.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <iostream>
#include <algorithm>
#include <chrono>
#include <ctime>
#include <memory>

namespace {

using namespace voxc;

struct BenchOptions {
    bool json = false;
    std::vector<int> sizes{64, 128, 256};
    std::vector<int> fieldSizes{256};
    std::vector<int> meshSizes{32, 256};
    std::vector<int> terrainSides{512};
    std::vector<std::string> backends{"vulkan", "interp", "libnoise", "host", "openvdb"};
    std::string device = "auto";
    int repetitions = 3;
};

// readBack false: the result stays in the device's buffers, as `voxc run` leaves it when it meshes
// there and writes no voxels (backend "vulkan_on_device").
void registerVulkan(bench::JsonReporter& reporter, VulkanContext& context, const std::string& caseName, int n,
                    std::shared_ptr<const Program> program, bool readBack = true) {
    const std::string backend = readBack ? "vulkan" : "vulkan_on_device";
    const std::string name = fmt::format("{}/{}/{}", caseName, n, backend);
    auto executor = std::make_shared<std::unique_ptr<VulkanExecutor>>();
    const bench::RecordKey setupKey{caseName, n, backend + "_setup", context.device().name};
    benchmark::RegisterBenchmark(name.c_str(), [&context, &reporter, setupKey, program, executor,
                                                readBack](benchmark::State& state) {
        if (!*executor) {
            const auto start = std::chrono::steady_clock::now();
            *executor = std::make_unique<VulkanExecutor>(context, compileProgram(*program, {}),
                                                         ExecutorOptions{.readBack = readBack});
            reporter.addRecord(setupKey, std::chrono::duration<double, std::milli>(
                                             std::chrono::steady_clock::now() - start).count());
            (*executor)->run(); // warm-up
        }
        double cpuMs = 0;
        for (auto _ : state) {
            const double cpuStart = bench::processCpuMs();
            const RunTimings t = (*executor)->run().timings;
            cpuMs += bench::processCpuMs() - cpuStart;
            state.SetIterationTime((t.recordMs + t.executeMs + t.readbackMs) / 1000.0);
        }
        state.counters["cpu_ms"] = benchmark::Counter(cpuMs, benchmark::Counter::kAvgIterations);
    })->UseManualTime()->Unit(benchmark::kMillisecond);
    reporter.describe(name + "/manual_time", {caseName, n, backend, context.device().name});
}

void registerInterp(bench::JsonReporter& reporter, const std::string& caseName, int n,
                    std::shared_ptr<const Program> program) {
    const std::string name = fmt::format("{}/{}/interp", caseName, n);
    auto warmedUp = std::make_shared<bool>(false);
    benchmark::RegisterBenchmark(name.c_str(), [program, warmedUp](benchmark::State& state) {
        if (!*warmedUp) benchmark::DoNotOptimize(interpret(*program).data().data()); // warm-up
        *warmedUp = true;
        double cpuMs = 0;
        for (auto _ : state) {
            const double cpuStart = bench::processCpuMs();
            benchmark::DoNotOptimize(interpret(*program).data().data());
            cpuMs += bench::processCpuMs() - cpuStart;
        }
        state.counters["cpu_ms"] = benchmark::Counter(cpuMs, benchmark::Counter::kAvgIterations);
    })->Unit(benchmark::kMillisecond);
    reporter.describe(name, {caseName, n, "interp", bench::interpDescription()});
}

// The field stage alone on the host (voxc::runField, FieldRowEvaluator on every core) into a grid
// made once, as the peers fill an array made once: fbm5's figure beside FastNoise2's.
void registerFieldHost(bench::JsonReporter& reporter, const std::string& caseName, int n,
                       std::shared_ptr<const Program> program) {
    const std::string name = fmt::format("{}/{}/host", caseName, n);
    benchmark::RegisterBenchmark(name.c_str(), [program](benchmark::State& state) {
        DenseGrid grid(program->world.size);
        const Stage& stage = program->pipeline.back();
        runField(*program, stage, grid); // warm-up: the grid's pages, the threads' first run
        double cpuMs = 0;
        for (auto _ : state) {
            const double cpuStart = bench::processCpuMs();
            runField(*program, stage, grid);
            benchmark::DoNotOptimize(grid.data().data());
            cpuMs += bench::processCpuMs() - cpuStart;
        }
        state.counters["cpu_ms"] = benchmark::Counter(cpuMs, benchmark::Counter::kAvgIterations);
    })->Unit(benchmark::kMillisecond)->UseRealTime();
    reporter.describe(name + "/real_time", {caseName, n, "host", bench::fieldHostDescription()});
}

void registerLibnoise(bench::JsonReporter& reporter, int n) {
    const std::string name = fmt::format("fbm5/{}/libnoise", n);
    benchmark::RegisterBenchmark(name.c_str(), [n](benchmark::State& state) {
        for (auto _ : state) benchmark::DoNotOptimize(bench::libnoiseFbm5(n).data());
    })->Unit(benchmark::kMillisecond)->UseRealTime();
    reporter.describe(name + "/real_time", {"fbm5", n, "libnoise", bench::libnoiseDescription()});
}

} // namespace

int main(int argc, char** argv) {
    BenchOptions options;
    CLI::App app{"voxc-bench: voxc (Vulkan) vs. the interpreter on the grammar examples"};
    app.allow_extras(); // the rest goes to Google Benchmark (e.g. --benchmark_min_time=2)
    app.add_flag("--json", options.json, "Print a JSON list of records");
    app.add_option("--sizes", options.sizes, "Grid sizes n (n^3 voxels)")->delimiter(',');
    app.add_option("--field-sizes", options.fieldSizes, "Grid sizes n of the fbm5 and feature cases")->delimiter(',');
    app.add_option("--mesh-sizes", options.meshSizes, "Grid sizes n of the meshing cases")->delimiter(',');
    app.add_option("--terrain-sides", options.terrainSides,
                   "Map sides of terrain_mountain_river (powers of two up to 4096; bench/terrain-2048.sh: 2048)")
        ->delimiter(',')
        ->check(CLI::Range(8, 4096));
    app.add_option("--backends", options.backends,
                   "vulkan, interp, libnoise, host (L-system expansion, CPU meshers), openvdb (meshing peer)")
        ->delimiter(',');
    app.add_option("--device", options.device, "Vulkan device: auto, lavapipe, gpu or an index");
    app.add_option("--repetitions", options.repetitions,
                   "Run every case this many times; the record holds the median and the min and max")
        ->check(CLI::PositiveNumber);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        return app.exit(error) == 0 ? 0 : 1;
    }
    std::vector<std::string> extras = app.remaining();
    std::string repetitionsFlag = fmt::format("--benchmark_repetitions={}", options.repetitions);
    std::vector<char*> benchArgs{argv[0], repetitionsFlag.data()};
    for (std::string& extra : extras) benchArgs.push_back(extra.data());
    int benchArgc = int(benchArgs.size());
    benchmark::Initialize(&benchArgc, benchArgs.data());

    try {
        bench::JsonReporter reporter;
        std::unique_ptr<VulkanContext> context;
        auto uses = [&](const char* backend) {
            return std::find(options.backends.begin(), options.backends.end(), backend) != options.backends.end();
        };
        if (uses("vulkan")) context = std::make_unique<VulkanContext>(ContextOptions{.device = options.device});
        for (const bench::Case& benchCase : bench::grammarCases()) {
            for (int n : options.sizes) {
                auto program = std::make_shared<const Program>(bench::loadCaseProgram(benchCase, n));
                if (uses("vulkan")) registerVulkan(reporter, *context, benchCase.name, n, program);
                if (uses("interp")) registerInterp(reporter, benchCase.name, n, program);
            }
        }
        for (const bench::Case& benchCase : bench::featureCases()) {
            for (int n : options.fieldSizes) {
                auto program = std::make_shared<const Program>(bench::loadFeatureProgram(benchCase, n));
                if (uses("vulkan")) registerVulkan(reporter, *context, benchCase.name, n, program);
                if (uses("interp")) registerInterp(reporter, benchCase.name, n, program);
            }
        }
        // Grammar power at 128^3: a symmetric rule vs its hand-expanded variants, the stamp examples.
        for (const bench::Case& benchCase : bench::symmetryCases()) {
            auto program = std::make_shared<const Program>(bench::loadExampleProgram(benchCase.example));
            if (uses("vulkan")) registerVulkan(reporter, *context, benchCase.name, 128, program);
            if (uses("interp")) registerInterp(reporter, benchCase.name, 128, program);
        }
        for (const bench::Case& benchCase : bench::stampCases()) {
            auto program = std::make_shared<const Program>(bench::loadFeatureProgram(benchCase, 128));
            if (uses("vulkan")) registerVulkan(reporter, *context, benchCase.name, 128, program);
            if (uses("interp")) registerInterp(reporter, benchCase.name, 128, program);
        }
        for (int n : options.fieldSizes) {
            auto program = std::make_shared<const Program>(bench::fbm5Program(n));
            if (uses("vulkan")) registerVulkan(reporter, *context, "fbm5", n, program);
            if (uses("vulkan")) registerVulkan(reporter, *context, "fbm5", n, program, false);
            if (uses("interp")) registerInterp(reporter, "fbm5", n, program);
            if (uses("host")) registerFieldHost(reporter, "fbm5", n, program);
            if (uses("libnoise")) registerLibnoise(reporter, n);
        }
        if (uses("vulkan") || uses("interp")) bench::registerLsystemCarve(reporter, context.get(), uses("interp"));
        // The whole cave network of examples/caves.vox (256x96x256): carve and two speleothem stages.
        if (uses("vulkan") || uses("interp")) {
            auto program = std::make_shared<const Program>(bench::loadExampleProgram("examples/caves.vox"));
            if (uses("vulkan")) registerVulkan(reporter, *context, "caves_example", 256, program);
            if (uses("interp")) registerInterp(reporter, "caves_example", 256, program);
        }
        for (int n : {128, 256})
            for (bool withStage : {false, true}) {
                auto program = std::make_shared<const Program>(bench::speleothemProgram(n, withStage));
                const std::string name = withStage ? "speleothems" : "speleothems_base";
                if (uses("vulkan")) registerVulkan(reporter, *context, name, n, program);
                if (uses("interp")) registerInterp(reporter, name, n, program);
            }
        // Existing terrain in: a 4096^2 heightmap sampled over 512x128x512, a 100k-triangle mesh's SDF.
        if (uses("vulkan") || uses("interp")) {
            auto program = std::make_shared<const Program>(bench::heightmapProgram());
            if (uses("vulkan")) registerVulkan(reporter, *context, "heightmap", 512, program);
            if (uses("interp")) registerInterp(reporter, "heightmap", 512, program);
        }
        if (uses("host")) bench::registerMeshSdf(reporter);
        if (uses("vulkan") || uses("interp") || uses("host"))
            bench::registerCurves(reporter, context.get(), uses("interp"), uses("host"));
        if (uses("host")) bench::registerLsystemExpand(reporter);
        if (uses("host")) bench::registerErosion(reporter);
        // The erosion steps on a CPU device (lavapipe) take about four times the host's loop: GPUs only.
        bench::registerTerrainSchedule(reporter, options.terrainSides, uses("host"),
                                       context && context->device().type != DeviceType::Cpu ? context.get() : nullptr);
        if (uses("host")) bench::registerCompileCases(reporter);
        if (uses("vulkan")) bench::registerStampSymmetryCompile(reporter);
        if (uses("host")) bench::registerLspLatency(reporter);
        // The meshing cases' grids come from the Vulkan pipeline, so they need the device.
        if (context) bench::registerMeshCases(reporter, *context, options.meshSizes, uses("host"), uses("vulkan"), uses("openvdb"));
        if (context) bench::registerViewFrame(reporter, *context);
        if (context) bench::registerWorldCases(reporter, *context);
        if (options.json) {
            benchmark::RunSpecifiedBenchmarks(&reporter);
        } else {
            benchmark::RunSpecifiedBenchmarks();
        }
        // The registered benchmarks own executors that must be destroyed before the context.
        benchmark::ClearRegisteredBenchmarks();
        benchmark::Shutdown();
    } catch (const UserError& error) {
        std::cerr << "voxc-bench: error: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
