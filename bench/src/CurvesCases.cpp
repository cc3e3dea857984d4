// curves: examples/curves_cliff.vox scaled to 128x64x128 (S = 1) and 256x128x256 (S = 2); Becher
// et al. Table 1 reports 131.69 ms and 1,480.82 ms for their 128^3 and 256x128x256 scenes on a GTX
// 1080, solve and meshing together. `host_solve` checks the file and solves it on the host (the
// interpreter's reference), `vulkan_solve` with every global pass on the device (vulkanCurvesSolvers:
// the multigrid, fronts, smoothing and displacement; spline to voxelisation and the density on the
// host; stages::solveBlocks), each with the parts' times as counters (SolveTable::phaseMs); the
// runs (`vulkan`, `interp`) combine the solved table.
#include "CurvesCases.h"

#include "voxc/check/Check.h"
#include "voxc/core/Errors.h"
#include "voxc/core/Simd.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Solve.h"
#include "voxc/vulkan/Executor.h"
#include "voxc/vulkan/GpuCurves.h"

#include <fmt/format.h>

#include <chrono>
#include <memory>

namespace voxc::bench {

namespace {

// The scene at scale S (its text's `const S`).
constexpr const char* kCurvesProgram = R"(
const S = 1;
world { size = [128 * S, 64 * S, 128 * S]; chunk = 32; }
material sand { id = 1; }
material sandstone { id = 2; }
material grass { id = 3; }
curves cliffs {
  box = [[0, 0, 0], [128 * S - 1, 64 * S - 1, 128 * S - 1]];
  noise_frequency = 0.0625;
  curve ground {
    points = [[28 * S, 10 * S, -4 * S], [28 * S, 10 * S, 40 * S], [28 * S, 10 * S, 86 * S], [28 * S, 10 * S, 130 * S]];
    constraint { t = 0; left = [42 * S, 0, 0]; right = [-24 * S, 0, 0]; material = sand; amplitude = 1; }
    constraint { t = 1; left = [42 * S, 0, 0]; right = [-24 * S, 0, 0]; material = sand; amplitude = 1; }
  }
  curve face {
    points = [[72 * S, 24 * S, -4 * S], [68 * S, 24 * S, 40 * S], [76 * S, 24 * S, 86 * S], [72 * S, 24 * S, 130 * S]];
    constraint { t = 0; left = [-8 * S, 20 * S, 0]; right = [0, -14 * S, 0]; material = sandstone; amplitude = 3; roughness = 0.6; }
    constraint { t = 0.5; left = [-12 * S, 20 * S, 0]; right = [0, -14 * S, 0]; material = sandstone; amplitude = 2; }
    constraint { t = 1; left = [-6 * S, 20 * S, 0]; right = [0, -14 * S, 0]; material = sandstone; amplitude = 3; roughness = 0.6; }
  }
  curve plateau {
    points = [[96 * S, 44 * S, -4 * S], [96 * S, 44 * S, 40 * S], [96 * S, 44 * S, 86 * S], [96 * S, 44 * S, 130 * S]];
    constraint { t = 0; left = [28 * S, 0, 0]; right = [-24 * S, 0, 0]; material = grass; amplitude = 1; }
    constraint { t = 1; left = [28 * S, 0, 0]; right = [-24 * S, 0, 0]; material = grass; amplitude = 1; }
  }
  curve sky {
    seed = false;
    points = [[64 * S, 56 * S, -4 * S], [64 * S, 56 * S, 40 * S], [64 * S, 56 * S, 86 * S], [64 * S, 56 * S, 130 * S]];
    constraint { t = 0; left = [16 * S, 0, 0]; right = [-16 * S, 0, 0]; material = grass; }
    constraint { t = 1; left = [16 * S, 0, 0]; right = [-16 * S, 0, 0]; material = grass; }
  }
}
pipeline { start; set cliffs; }
)";

// The scene checked and solved with `solvers`.
Program curvesProgram(int32_t scale, const curves::Solvers& solvers) {
    CheckOptions options;
    options.constOverrides["S"] = scale;
    CheckResult result = checkSource(SourceFile("curves.vox", kCurvesProgram), options);
    if (result.hasErrors() || !result.program)
        throw InternalError("the curves bench program does not check:\n" + result.rendered());
    Program program = std::move(*result.program);
    stages::solveBlocks(program, {solvers});
    return program;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// A check and solve of the scene per iteration, the solve's parts as counters (ms of the last iteration).
void registerSolve(JsonReporter& reporter, int32_t scale, const std::string& backend, const std::string& device,
                   std::function<curves::Solvers()> solvers) {
    const int n = 128 * scale;
    const std::string name = fmt::format("curves/{}_solve/{}", backend, n);
    auto* b = benchmark::RegisterBenchmark(name.c_str(), [scale, solvers](benchmark::State& state) {
        const curves::Solvers passes = solvers();
        for (auto _ : state) {
            const auto start = std::chrono::steady_clock::now();
            const Program program = curvesProgram(scale, passes);
            state.SetIterationTime(millisecondsSince(start) / 1000.0);
            for (const auto& [part, ms] : program.curves.front().solved().phaseMs) state.counters[part + "_ms"] = ms;
        }
    });
    b->UseManualTime()->Unit(benchmark::kMillisecond);
    if (scale > 1) b->Iterations(1); // a minute per check on the host; the run's name says so
    reporter.describe(name + (scale > 1 ? "/iterations:1" : "") + "/manual_time", {"curves_solve", n, backend, device});
}

} // namespace

void registerCurves(JsonReporter& reporter, VulkanContext* context, bool interp, bool host) {
    for (int32_t scale : {1, 2}) {
        const int n = 128 * scale;
        if (host)
            registerSolve(reporter, scale, "host", fmt::format("cpu (2 threads, {} kernels)", simdName(hostSimd())),
                          [] { return curves::Solvers{}; });
        if (context)
            registerSolve(reporter, scale, "vulkan", context->device().name,
                          [context] { return vulkanCurvesSolvers([context] { return context; }); });
        // Solved on the host, which is faster on lavapipe; the table is the same either way.
        auto program = std::make_shared<std::unique_ptr<const Program>>();
        const auto solved = [program, scale] {
            if (!*program) *program = std::make_unique<const Program>(curvesProgram(scale, curves::Solvers{}));
            return (*program).get();
        };
        if (context) {
            const std::string name = fmt::format("curves/vulkan/{}", n);
            auto executor = std::make_shared<std::unique_ptr<VulkanExecutor>>();
            benchmark::RegisterBenchmark(name.c_str(), [context, solved, executor](benchmark::State& state) {
                if (!*executor) {
                    *executor = std::make_unique<VulkanExecutor>(*context, compileProgram(*solved(), {}));
                    (*executor)->run(); // warm-up: first-use costs of the pipelines and buffers
                }
                for (auto _ : state) {
                    const RunTimings t = (*executor)->run().timings;
                    state.SetIterationTime((t.recordMs + t.executeMs + t.readbackMs) / 1000.0);
                }
            })->UseManualTime()->Unit(benchmark::kMillisecond);
            reporter.describe(name + "/manual_time", {"curves", n, "vulkan", context->device().name});
        }
        if (interp) {
            const std::string name = fmt::format("curves/interp/{}", n);
            benchmark::RegisterBenchmark(name.c_str(), [solved](benchmark::State& state) {
                const Program& checked = *solved();
                for (auto _ : state) {
                    const auto start = std::chrono::steady_clock::now();
                    benchmark::DoNotOptimize(interpret(checked).data().data());
                    state.SetIterationTime(millisecondsSince(start) / 1000.0);
                }
            })->UseManualTime()->Unit(benchmark::kMillisecond);
            reporter.describe(name + "/manual_time", {"curves", n, "interp", "cpu (1 thread)"});
        }
    }
}

} // namespace voxc::bench
