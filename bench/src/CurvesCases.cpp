// curves: examples/curves_cliff.vox scaled to 128x64x128 (Becher et al. Table 1 reports 131.69 ms
// for their 128^3 scene on a GTX 1080, solve and meshing together). The solve runs on the host
// when the file is checked, so it is its own record; the runs combine the solved table.
#include "CurvesCases.h"

#include "voxc/check/Check.h"
#include "voxc/core/Errors.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/vulkan/Executor.h"

#include <chrono>
#include <memory>

namespace voxc::bench {

namespace {

constexpr int kSize = 128;

constexpr const char* kCurvesProgram = R"(
world { size = [128, 64, 128]; chunk = 32; }
material sand { id = 1; }
material sandstone { id = 2; }
material grass { id = 3; }
curves cliffs {
  box = [[0, 0, 0], [127, 63, 127]];
  noise_frequency = 0.0625;
  curve ground {
    points = [[28, 10, -4], [28, 10, 40], [28, 10, 86], [28, 10, 130]];
    constraint { t = 0; left = [42, 0, 0]; right = [-24, 0, 0]; material = sand; amplitude = 1; }
    constraint { t = 1; left = [42, 0, 0]; right = [-24, 0, 0]; material = sand; amplitude = 1; }
  }
  curve face {
    points = [[72, 24, -4], [68, 24, 40], [76, 24, 86], [72, 24, 130]];
    constraint { t = 0; left = [-8, 20, 0]; right = [0, -14, 0]; material = sandstone; amplitude = 3; roughness = 0.6; }
    constraint { t = 0.5; left = [-12, 20, 0]; right = [0, -14, 0]; material = sandstone; amplitude = 2; }
    constraint { t = 1; left = [-6, 20, 0]; right = [0, -14, 0]; material = sandstone; amplitude = 3; roughness = 0.6; }
  }
  curve plateau {
    points = [[96, 44, -4], [96, 44, 40], [96, 44, 86], [96, 44, 130]];
    constraint { t = 0; left = [28, 0, 0]; right = [-24, 0, 0]; material = grass; amplitude = 1; }
    constraint { t = 1; left = [28, 0, 0]; right = [-24, 0, 0]; material = grass; amplitude = 1; }
  }
  curve sky {
    seed = false;
    points = [[64, 56, -4], [64, 56, 40], [64, 56, 86], [64, 56, 130]];
    constraint { t = 0; left = [16, 0, 0]; right = [-16, 0, 0]; material = grass; }
    constraint { t = 1; left = [16, 0, 0]; right = [-16, 0, 0]; material = grass; }
  }
}
pipeline { start; set cliffs; }
)";

Program curvesProgram() {
    CheckResult result = checkSource(SourceFile("curves.vox", kCurvesProgram));
    if (result.hasErrors() || !result.program)
        throw InternalError("the curves bench program does not check:\n" + result.rendered());
    return std::move(*result.program);
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

void registerCurves(JsonReporter& reporter, VulkanContext* context, bool interp, bool host) {
    if (host) {
        const std::string name = "curves/host_solve";
        benchmark::RegisterBenchmark(name.c_str(), [](benchmark::State& state) {
            for (auto _ : state) {
                const auto start = std::chrono::steady_clock::now();
                benchmark::DoNotOptimize(curvesProgram().curves.data());
                state.SetIterationTime(millisecondsSince(start) / 1000.0);
            }
        })->UseManualTime()->Unit(benchmark::kMillisecond);
        reporter.describe(name + "/manual_time", {"curves", kSize, "host", "cpu (1 thread)"});
    }
    auto program = std::make_shared<std::unique_ptr<const Program>>();
    const auto solved = [program] {
        if (!*program) *program = std::make_unique<const Program>(curvesProgram());
        return (*program).get();
    };
    if (context) {
        const std::string name = "curves/vulkan";
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
        reporter.describe(name + "/manual_time", {"curves", kSize, "vulkan", context->device().name});
    }
    if (interp) {
        const std::string name = "curves/interp";
        benchmark::RegisterBenchmark(name.c_str(), [solved](benchmark::State& state) {
            const Program& checked = *solved();
            for (auto _ : state) {
                const auto start = std::chrono::steady_clock::now();
                benchmark::DoNotOptimize(interpret(checked).data().data());
                state.SetIterationTime(millisecondsSince(start) / 1000.0);
            }
        })->UseManualTime()->Unit(benchmark::kMillisecond);
        reporter.describe(name + "/manual_time", {"curves", kSize, "interp", "cpu (1 thread)"});
    }
}

} // namespace voxc::bench
