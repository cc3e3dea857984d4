#include "voxc/builtins/NoiseBatch.h"

#include "Noise.h"
#include "NoiseCommon.h"
#include "NoiseLanes.h"
#include "voxc/core/Simd.h"

#include <algorithm>
#include <array>
#include <cmath>

#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#define VOXC_NOISE_AVX2 1
#endif

namespace voxc {

namespace {

#ifdef VOXC_NOISE_AVX2
// noise::perlin3 (GradientNoise.cpp) and noise::warpedFbm (Fractal.cpp) over a register of lanes:
// the same operations in the same order, so every lane rounds as the scalar code does. Selects
// replace the scalar branches; a lane with a non-finite coordinate computes with a masked lattice
// index and returns NaN, as the scalar code does without computing. Each width below brings in
// NoiseLanes.h's arithmetic and defines its other primitives, then NoiseBatchLanes.inc writes the
// noise once over them.

// Eight lanes (AVX2).
namespace lanes8 {
#define LANES __attribute__((target("avx2")))

using namespace noise::simd8; // Floats, add, sub, mul, splat, floorOf
using Ints = __m256i;
using Finite = __m256; // all ones where a lane's three coordinates are finite

LANES inline Floats load(const float* from) { return _mm256_loadu_ps(from); }
LANES inline void store(float* to, Floats v) { _mm256_storeu_ps(to, v); }
LANES inline Ints plus(Ints a, Ints b) { return _mm256_add_epi32(a, b); }
LANES inline Ints plus(Ints a, int b) { return _mm256_add_epi32(a, _mm256_set1_epi32(b)); }

// (floored - 256 * floor(floored / 256) + offset) & 255: the wrapped lattice index plus the seed's offset.
LANES inline Ints lattice(Floats floored, int offset) {
    const Floats wrapped = sub(floored, mul(splat(256.0f), floorOf(mul(floored, splat(0.00390625f)))));
    return _mm256_and_si256(plus(_mm256_cvttps_epi32(wrapped), offset), _mm256_set1_epi32(255));
}

// The permutation pair (perm(i) | perm(i + 1) << 8) at i & 255, and its two halves.
LANES inline Ints pairAt(const int* pairs, Ints i) {
    return _mm256_i32gather_epi32(pairs, _mm256_and_si256(i, _mm256_set1_epi32(255)), 4);
}
LANES inline Ints low(Ints pair) { return _mm256_and_si256(pair, _mm256_set1_epi32(255)); }
LANES inline Ints high(Ints pair) { return _mm256_srli_epi32(pair, 8); }

LANES inline Floats select(Ints condition, Floats whenTrue, Floats whenFalse) {
    return _mm256_blendv_ps(whenFalse, whenTrue, _mm256_castsi256_ps(condition));
}

LANES inline Floats grad(Ints hash, Floats x, Floats y, Floats z) {
    const Ints h = _mm256_and_si256(hash, _mm256_set1_epi32(15));
    const Floats u = select(_mm256_cmpgt_epi32(_mm256_set1_epi32(8), h), x, y);
    const Ints is12or14 = _mm256_or_si256(_mm256_cmpeq_epi32(h, _mm256_set1_epi32(12)),
                                          _mm256_cmpeq_epi32(h, _mm256_set1_epi32(14)));
    const Floats v = select(_mm256_cmpgt_epi32(_mm256_set1_epi32(4), h), y, select(is12or14, x, z));
    const Floats sign = splat(-0.0f);
    const Ints bit1 = _mm256_cmpeq_epi32(_mm256_and_si256(h, _mm256_set1_epi32(1)), _mm256_setzero_si256());
    const Ints bit2 = _mm256_cmpeq_epi32(_mm256_and_si256(h, _mm256_set1_epi32(2)), _mm256_setzero_si256());
    return add(select(bit1, u, _mm256_xor_ps(u, sign)), select(bit2, v, _mm256_xor_ps(v, sign)));
}

LANES inline Finite isFinite(Floats v) {
    // |v| < infinity is false for infinities and NaN.
    const Floats magnitude = _mm256_andnot_ps(splat(-0.0f), v);
    return _mm256_cmp_ps(magnitude, splat(INFINITY), _CMP_LT_OQ);
}

LANES inline Finite finiteLanes(Floats x, Floats y, Floats z) {
    return _mm256_and_ps(_mm256_and_ps(isFinite(x), isFinite(y)), isFinite(z));
}

LANES inline Floats nanUnless(Finite finite, Floats v) { return _mm256_blendv_ps(splat(noise::kNaN), v, finite); }

#include "NoiseBatchLanes.inc"
#undef LANES
} // namespace lanes8

// Sixteen lanes where the CPU has AVX-512 (AVX512F only): compares into mask registers, sign
// flips and magnitudes as integer bit operations.
namespace lanes16 {
#define LANES __attribute__((target("avx512f")))

using namespace noise::simd16; // Floats, add, sub, mul, splat, floorOf
using Ints = __m512i;
using Finite = __mmask16;

LANES inline Floats load(const float* from) { return _mm512_loadu_ps(from); }
LANES inline void store(float* to, Floats v) { _mm512_storeu_ps(to, v); }
LANES inline Ints plus(Ints a, Ints b) { return _mm512_add_epi32(a, b); }
LANES inline Ints plus(Ints a, int b) { return _mm512_add_epi32(a, _mm512_set1_epi32(b)); }

LANES inline Ints lattice(Floats floored, int offset) {
    const Floats wrapped = sub(floored, mul(splat(256.0f), floorOf(mul(floored, splat(0.00390625f)))));
    // (the unmasked conversion reads an undefined register)
    return _mm512_and_si512(plus(_mm512_maskz_cvttps_epi32(0xFFFF, wrapped), offset), _mm512_set1_epi32(255));
}

LANES inline Ints pairAt(const int* pairs, Ints i) {
    return _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), 0xFFFF, _mm512_and_si512(i, _mm512_set1_epi32(255)),
                                       pairs, 4);
}
LANES inline Ints low(Ints pair) { return _mm512_and_si512(pair, _mm512_set1_epi32(255)); }
// (the unmasked shift reads an undefined register)
LANES inline Ints high(Ints pair) { return _mm512_maskz_srli_epi32(0xFFFF, pair, 8); }

LANES inline Floats flippedSign(Floats v) {
    return _mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(v), _mm512_set1_epi32(int32_t(0x80000000u))));
}

LANES inline Floats grad(Ints hash, Floats x, Floats y, Floats z) {
    const Ints h = _mm512_and_si512(hash, _mm512_set1_epi32(15));
    const Floats u = _mm512_mask_blend_ps(_mm512_cmplt_epi32_mask(h, _mm512_set1_epi32(8)), y, x);
    const __mmask16 is12or14 = _mm512_cmpeq_epi32_mask(h, _mm512_set1_epi32(12)) | _mm512_cmpeq_epi32_mask(h, _mm512_set1_epi32(14));
    const Floats v = _mm512_mask_blend_ps(_mm512_cmplt_epi32_mask(h, _mm512_set1_epi32(4)),
                                          _mm512_mask_blend_ps(is12or14, z, x), y);
    const __mmask16 bit1 = _mm512_testn_epi32_mask(h, _mm512_set1_epi32(1));
    const __mmask16 bit2 = _mm512_testn_epi32_mask(h, _mm512_set1_epi32(2));
    return add(_mm512_mask_blend_ps(bit1, flippedSign(u), u), _mm512_mask_blend_ps(bit2, flippedSign(v), v));
}

LANES inline Finite isFinite(Floats v) {
    const Floats magnitude =
        _mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(v), _mm512_set1_epi32(0x7fffffff)));
    return _mm512_cmp_ps_mask(magnitude, splat(INFINITY), _CMP_LT_OQ);
}

LANES inline Finite finiteLanes(Floats x, Floats y, Floats z) { return isFinite(x) & isFinite(y) & isFinite(z); }

LANES inline Floats nanUnless(Finite finite, Floats v) { return _mm512_mask_blend_ps(finite, splat(noise::kNaN), v); }

#include "NoiseBatchLanes.inc"
#undef LANES
} // namespace lanes16
#endif

} // namespace

void warpedFbmBatch(const float* x, const float* y, const float* z, const float* roughness, float warpLow,
                    float warpHigh, uint32_t seed, size_t n, float* out) {
    size_t i = 0;
#ifdef VOXC_NOISE_AVX2
    const Simd simd = hostSimd();
    if (simd >= Simd::Avx2) {
        const int* pairs = noise::permutationPairs().data();
        const int offsets[3] = {noise::seedOffset(seed, 0), noise::seedOffset(seed, 1), noise::seedOffset(seed, 2)};
        if (simd == Simd::Avx512)
            for (; i + 16 <= n; i += 16) {
                float base[16];
                for (int lane = 0; lane < 16; ++lane) base[lane] = std::exp2(-(1.0f - roughness[i + size_t(lane)]));
                lanes16::warpedFbm(x + i, y + i, z + i, base, warpLow, warpHigh, pairs, offsets, out + i);
            }
        for (; i + 8 <= n; i += 8) {
            // The layer amplitude's base 2^-(1 - R), by the scalar exp2 (libm's, as warpedFbm's).
            float base[8];
            for (int lane = 0; lane < 8; ++lane) base[lane] = std::exp2(-(1.0f - roughness[i + size_t(lane)]));
            lanes8::warpedFbm(x + i, y + i, z + i, base, warpLow, warpHigh, pairs, offsets, out + i);
        }
        if (i < n) {
            // The last 1-7 points in one register too, padded with copies of the last one (lanes
            // are independent): the scalar code took as long per point as the register for
            // eight.
            float px[8], py[8], pz[8], base[8], result[8];
            for (size_t lane = 0; lane < 8; ++lane) {
                const size_t j = std::min(i + lane, n - 1);
                px[lane] = x[j], py[lane] = y[j], pz[lane] = z[j];
                base[lane] = std::exp2(-(1.0f - roughness[j]));
            }
            lanes8::warpedFbm(px, py, pz, base, warpLow, warpHigh, pairs, offsets, result);
            for (size_t lane = 0; i + lane < n; ++lane) out[i + lane] = result[lane];
            i = n;
        }
    }
#endif
    for (; i < n; ++i) out[i] = noise::warpedFbm({x[i], y[i], z[i]}, roughness[i], warpLow, warpHigh, seed);
}

} // namespace voxc
