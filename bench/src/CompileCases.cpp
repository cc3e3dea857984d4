// Codegen time should grow about linearly with the program up to every documented limit.
#include "CompileCases.h"

#include "voxc/check/Check.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/core/Errors.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

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

// CPU seconds (user + system, every thread) of one `voxc run FILE` on lavapipe with every cache
// off: GLSL, SPIR-V and the driver's code compiled afresh, as on a first run.
double coldRunCpuSeconds(const std::string& file, const std::string& mesh) {
    const pid_t child = ::fork();
    if (child < 0) throw UserError("stamp_symmetry_compile: cannot fork");
    if (child == 0) {
        ::setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
        // Its report would interleave with the bench's: the CPU time is all that is kept.
        const int null = ::open("/dev/null", O_WRONLY);
        if (null >= 0) ::dup2(null, 1), ::dup2(null, 2);
        const char* argv[] = {VOXC_BINARY, "run", file.c_str(), "--no-cache", "--device", "lavapipe", "-o", mesh.c_str(), nullptr};
        ::execv(VOXC_BINARY, const_cast<char* const*>(argv));
        ::_exit(127);
    }
    int status = 0;
    rusage usage{};
    if (::wait4(child, &status, 0, &usage) != child || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw UserError(fmt::format("stamp_symmetry_compile: voxc run {} failed", file));
    return double(usage.ru_utime.tv_sec) + double(usage.ru_utime.tv_usec) * 1e-6 + double(usage.ru_stime.tv_sec) +
           double(usage.ru_stime.tv_usec) * 1e-6;
}

// bench/grammars/stamp_symmetry.vox with `symmetry = GROUP` written into a temporary file.
std::string stampSymmetryFile(const std::string& group) {
    std::ifstream in(std::string(VOXC_SOURCE_DIR) + "/bench/grammars/stamp_symmetry.vox");
    std::stringstream text;
    text << in.rdbuf();
    std::string source = text.str();
    const std::string none = "\n  symmetry = none;\n";
    const size_t at = source.find(none);
    if (at == std::string::npos) throw InternalError("bench/grammars/stamp_symmetry.vox lost its 'symmetry = none;'");
    source.replace(at, none.size(), "\n  symmetry = " + group + ";\n");
    const std::string path = fmt::format("/tmp/voxc-bench-stamp-symmetry-{}-{}.vox", group, ::getpid());
    std::ofstream(path) << source;
    return path;
}

} // namespace

void registerStampSymmetryCompile(JsonReporter& reporter) {
    // n = the group's variants of the rule: none 1, all 48.
    for (const auto& [group, variants] : {std::pair{"none", 1}, std::pair{"all", 48}}) {
        const std::string name = fmt::format("stamp_symmetry_compile/{}", variants);
        benchmark::RegisterBenchmark(name.c_str(), [group = std::string(group)](benchmark::State& state) {
            const std::string file = stampSymmetryFile(group), mesh = file + ".glb";
            coldRunCpuSeconds(file, mesh); // warm-up: the binary and Mesa's libraries in the page cache
            for (auto _ : state) state.SetIterationTime(coldRunCpuSeconds(file, mesh));
            ::unlink(mesh.c_str());
            ::unlink(file.c_str());
        })->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(3);
        reporter.describe(name + "/iterations:3/manual_time",
                          {"stamp_symmetry_compile", variants, "vulkan", "lavapipe, voxc run CPU, cold caches"});
    }
}

void registerCompileCases(JsonReporter& reporter) {
    // Warm-up: glslang's process initialisation and the shader templates, outside the timings.
    compileProgram(rulesProgram(1, 1, {2, 2, 2}));
    registerCase(reporter, "compile_8cube_rules", 8, rulesProgram(1, 8, {8, 8, 8}));
    registerCase(reporter, "compile_8cube_rules", 32, rulesProgram(4, 8, {8, 8, 8}));
    registerCase(reporter, "compile_16cell_rules", 256, rulesProgram(1, 256, {4, 2, 2}));
}

} // namespace voxc::bench
