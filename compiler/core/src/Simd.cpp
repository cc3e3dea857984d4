#include "voxc/core/Simd.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace voxc {
namespace {

Simd cpuSimd() {
#if defined(__x86_64__) || defined(__i386__)
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
        __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512cd"))
        return Simd::Avx512;
    if (__builtin_cpu_supports("avx2")) return Simd::Avx2;
#endif
    return Simd::None;
}

// A bad value only costs speed (every path gives the same bits), so it is a warning, not an
// error that would stop a solve on a worker thread.
Simd limitFromEnvironment(Simd cpu) {
    const char* value = std::getenv("VOXC_SIMD");
    if (!value || !*value) return cpu;
    for (const Simd simd : {Simd::None, Simd::Avx2, Simd::Avx512})
        if (std::strcmp(value, simdName(simd)) == 0) return simd < cpu ? simd : cpu;
    std::fprintf(stderr, "voxc: warning: VOXC_SIMD=%s is not one of avx512, avx2, none; using %s\n", value,
                 simdName(cpu));
    return cpu;
}

} // namespace

Simd hostSimd() {
    static const Simd simd = limitFromEnvironment(cpuSimd());
    return simd;
}

const char* simdName(Simd simd) {
    switch (simd) {
    case Simd::Avx512: return "avx512";
    case Simd::Avx2: return "avx2";
    case Simd::None: break;
    }
    return "none";
}

} // namespace voxc
