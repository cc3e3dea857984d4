#pragma once
// The float arithmetic every lane-generic noise kernel is written over (NoiseBatchLanes.inc,
// NoiseRowLanes.inc), per register width: each kernel's width namespace brings one in with a
// using-directive and adds its own primitives. One IEEE operation each, so a lane rounds as the
// scalar code does.
#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>

namespace voxc::noise {

namespace simd8 { // AVX2
#define VOXC_NOISE_LANES __attribute__((target("avx2")))
using Floats = __m256;
VOXC_NOISE_LANES inline Floats add(Floats a, Floats b) { return _mm256_add_ps(a, b); }
VOXC_NOISE_LANES inline Floats sub(Floats a, Floats b) { return _mm256_sub_ps(a, b); }
VOXC_NOISE_LANES inline Floats mul(Floats a, Floats b) { return _mm256_mul_ps(a, b); }
VOXC_NOISE_LANES inline Floats splat(float v) { return _mm256_set1_ps(v); }
VOXC_NOISE_LANES inline Floats floorOf(Floats v) { return _mm256_floor_ps(v); }
#undef VOXC_NOISE_LANES
} // namespace simd8

namespace simd16 { // AVX-512 F
#define VOXC_NOISE_LANES __attribute__((target("avx512f")))
using Floats = __m512;
VOXC_NOISE_LANES inline Floats add(Floats a, Floats b) { return _mm512_add_ps(a, b); }
VOXC_NOISE_LANES inline Floats sub(Floats a, Floats b) { return _mm512_sub_ps(a, b); }
VOXC_NOISE_LANES inline Floats mul(Floats a, Floats b) { return _mm512_mul_ps(a, b); }
VOXC_NOISE_LANES inline Floats splat(float v) { return _mm512_set1_ps(v); }
VOXC_NOISE_LANES inline Floats floorOf(Floats v) { return _mm512_floor_ps(v); }
#undef VOXC_NOISE_LANES
} // namespace simd16

} // namespace voxc::noise
#endif
