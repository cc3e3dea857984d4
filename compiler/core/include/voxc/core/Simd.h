#pragma once
// The widest instruction set the host's vectorised loops may use (the multigrid's and the
// erosion's row kernels and colour sweeps, the mesher's sign classification, the batched noise,
// the field rows and their fractal noise): what the CPU has, lowered by the environment variable
// VOXC_SIMD (`avx512`, `avx2` or `none`), read once per process. Every path computes the same
// bits, so the variable changes only speed: it lets a machine time and test the narrower paths it
// would otherwise never run.
#include <algorithm>
#include <utility>

namespace voxc {

enum class Simd {
    None,   // plain C++ (what the compiler vectorises for the baseline CPU)
    Avx2,   // AVX2
    Avx512, // AVX-512 F, BW, CD, DQ and VL (x86-64-v4)
};

Simd hostSimd();
const char* simdName(Simd simd);

// atHostSimd<kernel>(args...) calls kernel(args...) compiled for hostSimd(), at most `widest`:
// for loops the compiler vectorises. The kernel is declared VOXC_SIMD_KERNEL, so its body is
// inlined into, and compiled for, each wrapper's instruction set (GCC on x86-64; elsewhere a plain
// call). Unlike the compiler's function clones, which pick by the CPU alone, VOXC_SIMD reaches it.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define VOXC_SIMD_KERNEL inline __attribute__((always_inline))

namespace simd_wrappers {
template <auto kernel, typename... Args>
__attribute__((target("arch=x86-64-v4"))) decltype(auto) avx512(Args&&... args) {
    return kernel(std::forward<Args>(args)...);
}
template <auto kernel, typename... Args>
__attribute__((target("avx2"))) decltype(auto) avx2(Args&&... args) {
    return kernel(std::forward<Args>(args)...);
}
template <auto kernel, typename... Args>
__attribute__((noinline)) decltype(auto) baseline(Args&&... args) {
    return kernel(std::forward<Args>(args)...);
}
} // namespace simd_wrappers

template <auto kernel, Simd widest = Simd::Avx512, typename... Args>
decltype(auto) atHostSimd(Args&&... args) {
    const Simd simd = std::min(hostSimd(), widest);
    if constexpr (widest >= Simd::Avx512)
        if (simd == Simd::Avx512) return simd_wrappers::avx512<kernel>(std::forward<Args>(args)...);
    if constexpr (widest >= Simd::Avx2)
        if (simd == Simd::Avx2) return simd_wrappers::avx2<kernel>(std::forward<Args>(args)...);
    return simd_wrappers::baseline<kernel>(std::forward<Args>(args)...);
}
#else
#define VOXC_SIMD_KERNEL inline

template <auto kernel, Simd widest = Simd::Avx512, typename... Args>
decltype(auto) atHostSimd(Args&&... args) {
    return kernel(std::forward<Args>(args)...);
}
#endif

} // namespace voxc
