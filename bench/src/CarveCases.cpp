// lsystem_carve: milliseconds per 32^3 chunk of an L-system cave carve (issue 8's goal: at most 5 ms
// on lavapipe; Mark & Berechet report 228 ms per 32^3 tile on an HD 7750). A run is the start
// fill plus the carve; ms_per_chunk divides it by the chunks interval analysis leaves to evaluate.
#include "CarveCases.h"
#include "Cases.h"

#include "voxc/check/Check.h"
#include "voxc/core/Errors.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/ir/passes/ClassifyFieldChunks.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/vulkan/Executor.h"

#include <chrono>
#include <memory>

namespace voxc::bench {

namespace {

constexpr int kCarveChunk = 32;

constexpr const char* kCarveProgram = R"(
world { size = [128, 32, 128]; chunk = 32; seed = 7; }
start { fill { value = 1; } }
lsystem net {
  expansions = 4; angle = 45; step = 4; start = [8, 16, 64];
  production Z { "FZ[RFZ]FZ[LFZ[RF]]"; }
  connect { chance = 1; max_distance = 24; }
}
feature tunnels = lsystem_cave { lsystem = net; }
pipeline { start; subtract tunnels; }
)";

Program carveProgram() {
    CheckResult result = checkSource(SourceFile("lsystem_carve.vox", kCarveProgram));
    if (result.hasErrors() || !result.program)
        throw InternalError("the lsystem_carve bench program does not check:\n" + result.rendered());
    return std::move(*result.program);
}

// The chunks whose carve is evaluated (not proven constant).
int evaluatedChunks(const Program& program) {
    const Field& field = program.fields.back();
    const ir::IrField irField{field.name, field.loc, field.nodes, field.root, {}};
    int chunks = 0;
    for (const ir::FieldChunk& chunk : ir::classifyFieldChunks(program.world, irField)) chunks += !chunk.constant;
    return chunks;
}

} // namespace

void registerLsystemCarve(JsonReporter& reporter, VulkanContext* context, bool interp) {
    auto program = std::make_shared<const Program>(carveProgram());
    const int chunks = evaluatedChunks(*program);
    if (context) {
        const std::string name = "lsystem_carve/vulkan";
        auto executor = std::make_shared<std::unique_ptr<VulkanExecutor>>();
        benchmark::RegisterBenchmark(name.c_str(), [context, program, executor, chunks](benchmark::State& state) {
            if (!*executor) {
                *executor = std::make_unique<VulkanExecutor>(*context, compileProgram(*program, {}));
                (*executor)->run(); // warm-up: first-use costs of the pipelines and buffers
            }
            double ms = 0, cpuMs = 0;
            for (auto _ : state) {
                const double cpuStart = processCpuMs();
                const RunTimings t = (*executor)->run().timings;
                cpuMs += processCpuMs() - cpuStart;
                const double run = t.recordMs + t.executeMs + t.readbackMs;
                state.SetIterationTime(run / 1000.0);
                ms += run;
            }
            state.counters["chunks"] = chunks;
            state.counters["ms_per_chunk"] = ms / double(state.iterations()) / chunks;
            // CPU time of every thread per run: steadier than the wall time on a loaded machine.
            state.counters["cpu_ms"] = cpuMs / double(state.iterations());
        })->UseManualTime()->Unit(benchmark::kMillisecond);
        reporter.describe(name + "/manual_time", {"lsystem_carve", kCarveChunk, "vulkan", context->device().name});
    }
    if (interp) {
        const std::string name = "lsystem_carve/interp";
        benchmark::RegisterBenchmark(name.c_str(), [program, chunks](benchmark::State& state) {
            benchmark::DoNotOptimize(interpret(*program).data().data()); // warm-up
            double ms = 0;
            for (auto _ : state) {
                const auto start = std::chrono::steady_clock::now();
                benchmark::DoNotOptimize(interpret(*program).data().data());
                const double run =
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
                state.SetIterationTime(run / 1000.0);
                ms += run;
            }
            state.counters["chunks"] = chunks;
            state.counters["ms_per_chunk"] = ms / double(state.iterations()) / chunks;
        })->UseManualTime()->Unit(benchmark::kMillisecond);
        reporter.describe(name + "/manual_time", {"lsystem_carve", kCarveChunk, "interp", "cpu (1 thread)"});
    }
}

} // namespace voxc::bench
