#include "Cases.h"

#include "voxc/check/Check.h"
#include "voxc/core/Errors.h"
#include "voxc/core/Simd.h"

#include <fmt/format.h>
#include <libnoise/noise.h>
#include <thread>
#include <time.h>

namespace voxc::bench {

Program fbm5Program(int n) {
    const std::string text = fmt::format("world {{ size = [{0}, {0}, {0}]; chunk = 32; }}\n"
                                         "field fbm5 = fbm(wp * 0.02, 5, 2.0, 0.5, 0);\n"
                                         "pipeline {{ start; set fbm5; }}\n",
                                         n);
    CheckResult result = checkSource(SourceFile("fbm5.vox", text));
    if (result.hasErrors() || !result.program) throw InternalError("the fbm5 bench program does not check:\n" + result.rendered());
    return std::move(*result.program);
}

double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

std::vector<float> libnoiseFbm5(int n) {
    std::vector<float> values(size_t(n) * n * n);
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> workers;
    for (unsigned t = 0; t < threads; ++t) {
        workers.emplace_back([&, t] {
            noise::module::Perlin perlin; // one module per thread: GetValue is const but keep them apart
            perlin.SetOctaveCount(5);
            perlin.SetFrequency(0.02);
            perlin.SetLacunarity(2.0);
            perlin.SetPersistence(0.5);
            perlin.SetSeed(0);
            perlin.SetNoiseQuality(noise::QUALITY_STD);
            for (int z = int(t); z < n; z += int(threads))
                for (int y = 0; y < n; ++y)
                    for (int x = 0; x < n; ++x)
                        values[size_t(x) + size_t(n) * (size_t(y) + size_t(n) * size_t(z))] =
                            float(perlin.GetValue(x, y, z));
        });
    }
    for (std::thread& worker : workers) worker.join();
    return values;
}

std::string fieldHostDescription() {
    return fmt::format("cpu ({} threads, {})", std::max(1u, std::thread::hardware_concurrency()), simdName(hostSimd()));
}

std::string interpDescription() {
    return fmt::format("cpu (grammars on 1 thread, field stages on {})", std::max(1u, std::thread::hardware_concurrency()));
}

std::string libnoiseDescription() {
    return fmt::format("cpu ({} threads, libnoise 1.0)", std::max(1u, std::thread::hardware_concurrency()));
}

} // namespace voxc::bench
