// voxc-bench: times the grammar cases on the Vulkan path and in the interpreter.
// `voxc-bench --json` prints a JSON list of records; without it Google Benchmark's table.
// Vulkan times cover execution and readback of an already-built package (pipelines compiled
// once up front: that cost is printed to stderr, not included); interpreter times cover the
// same work: start state plus one grammar iteration.
#include "Cases.h"
#include "JsonReporter.h"

#include "voxc/codegen/Codegen.h"
#include "voxc/core/Errors.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <iostream>
#include <memory>

namespace {

using namespace voxc;

struct BenchOptions {
    bool json = false;
    std::vector<int> sizes{64, 128, 256};
    std::vector<std::string> backends{"vulkan", "interp"};
    std::string device = "auto";
};

void registerVulkan(bench::JsonReporter& reporter, VulkanContext& context, const bench::Case& benchCase, int n) {
    const std::string name = fmt::format("{}/{}/vulkan", benchCase.name, n);
    auto program = std::make_shared<Program>(bench::loadCaseProgram(benchCase, n));
    auto executor = std::make_shared<std::unique_ptr<VulkanExecutor>>();
    benchmark::RegisterBenchmark(name.c_str(), [&context, program, executor](benchmark::State& state) {
        if (!*executor) {
            *executor = std::make_unique<VulkanExecutor>(context, codegen::compileProgram(*program, {}));
            std::cerr << fmt::format("vulkan setup (codegen + pipelines): {:.1f} ms\n",
                                     (*executor)->setupMs());
        }
        for (auto _ : state) {
            const RunTimings t = (*executor)->run().timings;
            state.SetIterationTime((t.recordMs + t.executeMs + t.readbackMs) / 1000.0);
        }
    })->UseManualTime()->Unit(benchmark::kMillisecond);
    reporter.describe(name + "/manual_time", {benchCase.name, n, "vulkan", context.device().name});
}

void registerInterp(bench::JsonReporter& reporter, const bench::Case& benchCase, int n) {
    const std::string name = fmt::format("{}/{}/interp", benchCase.name, n);
    auto program = std::make_shared<Program>(bench::loadCaseProgram(benchCase, n));
    benchmark::RegisterBenchmark(name.c_str(), [program](benchmark::State& state) {
        for (auto _ : state) benchmark::DoNotOptimize(interpret(*program).data().data());
    })->Unit(benchmark::kMillisecond);
    reporter.describe(name, {benchCase.name, n, "interp", "cpu (1 thread)"});
}

} // namespace

int main(int argc, char** argv) {
    BenchOptions options;
    CLI::App app{"voxc-bench: voxc (Vulkan) vs. the interpreter on the grammar examples"};
    app.allow_extras(); // the rest goes to Google Benchmark (e.g. --benchmark_min_time=2)
    app.add_flag("--json", options.json, "Print a JSON list of records");
    app.add_option("--sizes", options.sizes, "Grid sizes n (n^3 voxels)")->delimiter(',');
    app.add_option("--backends", options.backends, "vulkan, interp")->delimiter(',');
    app.add_option("--device", options.device, "Vulkan device: auto, lavapipe, gpu or an index");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        return app.exit(error) == 0 ? 0 : 1;
    }
    std::vector<std::string> extras = app.remaining();
    std::vector<char*> benchArgs{argv[0]};
    for (std::string& extra : extras) benchArgs.push_back(extra.data());
    int benchArgc = int(benchArgs.size());
    benchmark::Initialize(&benchArgc, benchArgs.data());

    try {
        bench::JsonReporter reporter;
        std::unique_ptr<VulkanContext> context;
        const bool useVulkan = std::find(options.backends.begin(), options.backends.end(), "vulkan") != options.backends.end();
        const bool useInterp = std::find(options.backends.begin(), options.backends.end(), "interp") != options.backends.end();
        if (useVulkan) context = std::make_unique<VulkanContext>(ContextOptions{.device = options.device});
        for (const bench::Case& benchCase : bench::grammarCases()) {
            for (int n : options.sizes) {
                if (useVulkan) registerVulkan(reporter, *context, benchCase, n);
                if (useInterp) registerInterp(reporter, benchCase, n);
            }
        }
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
