// Codegen time should grow about linearly with the program up to every documented limit.
#include "CompileCases.h"

#include "voxc/check/Check.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/core/Errors.h"

#include <fmt/format.h>
#include <memory>

namespace voxc::bench {

namespace {

// `grammars` grammars of `rules` rules with `window` windows, run in order; the cells cycle
// through density tests and writes (a fixed pseudo-random sequence) so that rules differ and
// most cells read and write.
Program rulesProgram(int grammars, int rules, glm::ivec3 window) {
    const char* symbols[] = {"GEQ 0.5", "LT 0.5", "IGN", "PRES", "ABS"};
    const char* transforms[] = {"NOP", "ADD -0.1", "SET 1", "SET 0"};
    uint32_t state = 1;
    const auto next = [&state](uint32_t n) {
        state = state * 1664525u + 1013904223u;
        return (state >> 16) % n;
    };
    std::string text = "world { size = [64, 64, 64]; chunk = 32; seed = 1; }\n"
                       "start { fill { value = 0; } box { min = [0, 0, 0]; max = [24, 64, 64]; value = 1; } }\n";
    std::string pipeline = "pipeline { start;";
    for (int g = 0; g < grammars; ++g) {
        text += fmt::format("grammar g{} {{\n  stride = [1, 1, 1];\n  iterations = 1;\n", g);
        pipeline += fmt::format(" g{};", g);
        for (int r = 0; r < rules; ++r) {
            text += fmt::format("  rule r{} {{\n    size = [{}, {}, {}];\n", r, window.x, window.y, window.z);
            for (const auto& [part, pool, count] :
                 {std::tuple{"symbol", symbols, 5u}, std::tuple{"transform", transforms, 4u}}) {
                text += fmt::format("    {} {{\n", part);
                for (int z = 0; z < window.z; ++z) {
                    text += "      layer {";
                    for (int y = 0; y < window.y; ++y) {
                        text += " [";
                        for (int x = 0; x < window.x; ++x)
                            text += fmt::format("{}{}", x ? ", " : "", pool[next(count)]);
                        text += "]";
                    }
                    text += " }\n";
                }
                text += "    }\n";
            }
            text += "  }\n";
        }
        text += "}\n";
    }
    text += pipeline + " }\n";
    CheckResult checked = checkSource(SourceFile("compile_case.vox", text));
    if (!checked.program) throw InternalError("the compile bench program does not check:\n" + checked.rendered());
    return std::move(*checked.program);
}

void registerCase(JsonReporter& reporter, const std::string& caseName, int rules, Program program) {
    auto shared = std::make_shared<const Program>(std::move(program));
    const std::string name = fmt::format("{}/{}", caseName, rules);
    benchmark::RegisterBenchmark(name.c_str(), [shared](benchmark::State& state) {
        for (auto _ : state) benchmark::DoNotOptimize(compileProgram(*shared).kernels.data());
    })->Unit(benchmark::kMillisecond)->UseRealTime();
    reporter.describe(name + "/real_time", {caseName, rules, "host", "cpu (1 thread)"});
}

} // namespace

void registerCompileCases(JsonReporter& reporter) {
    // Warm-up: glslang's process initialisation and the shader templates, outside the timings.
    compileProgram(rulesProgram(1, 1, {2, 2, 2}));
    registerCase(reporter, "compile_8cube_rules", 8, rulesProgram(1, 8, {8, 8, 8}));
    registerCase(reporter, "compile_8cube_rules", 32, rulesProgram(4, 8, {8, 8, 8}));
    registerCase(reporter, "compile_16cell_rules", 256, rulesProgram(1, 256, {4, 2, 2}));
}

} // namespace voxc::bench
