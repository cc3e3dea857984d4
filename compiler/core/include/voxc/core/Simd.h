#pragma once
// The widest instruction set the host's hand-vectorised loops may use (the multigrid's colour
// sweeps, the mesher's sign classification, the batched noise): what the CPU has, lowered by the
// environment variable VOXC_SIMD (`avx512`, `avx2` or `none`), read once per process. Every path
// computes the same bits, so the variable changes only speed: it lets a machine time and test the
// narrower paths it would otherwise never run.
namespace voxc {

enum class Simd {
    None,   // plain C++ (what the compiler vectorises for the baseline CPU)
    Avx2,   // AVX2
    Avx512, // AVX-512 F, BW, DQ and VL
};

Simd hostSimd();
const char* simdName(Simd simd);

} // namespace voxc
