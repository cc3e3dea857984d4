#include "voxc/builtins/NoiseBatch.h"

#include "Noise.h"
#include "NoiseCommon.h"

#include <algorithm>
#include <cmath>

#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#define VOXC_NOISE_AVX2 1
#endif

namespace voxc {

namespace {

#ifdef VOXC_NOISE_AVX2
// Eight lanes of noise::perlin3 (GradientNoise.cpp) and noise::warpedFbm (Fractal.cpp): the same
// operations in the same order, so every lane rounds as the scalar code does. Selects replace
// the scalar branches; a lane with a non-finite coordinate computes with a masked lattice index
// and returns NaN, as the scalar code does without computing.
#define AVX2 __attribute__((target("avx2")))

struct V3 {
    __m256 x, y, z;
};

AVX2 inline __m256 add(__m256 a, __m256 b) { return _mm256_add_ps(a, b); }
AVX2 inline __m256 sub(__m256 a, __m256 b) { return _mm256_sub_ps(a, b); }
AVX2 inline __m256 mul(__m256 a, __m256 b) { return _mm256_mul_ps(a, b); }
AVX2 inline __m256 splat(float v) { return _mm256_set1_ps(v); }

AVX2 inline __m256 fade(__m256 t) {
    // t * t * t * (t * (t * 6 - 15) + 10), left to right as C++ evaluates it.
    return mul(mul(mul(t, t), t), add(mul(t, sub(mul(t, splat(6.0f)), splat(15.0f))), splat(10.0f)));
}

AVX2 inline __m256 lerp(__m256 t, __m256 a, __m256 b) { return add(a, mul(t, sub(b, a))); }

// latticeIndex: floored - 256 * floor(floored / 256), an exact integer in [0, 256) for finite values.
AVX2 inline __m256i latticeIndex(__m256 floored) {
    const __m256 wrapped = sub(floored, mul(splat(256.0f), _mm256_floor_ps(mul(floored, splat(0.00390625f)))));
    return _mm256_cvttps_epi32(wrapped);
}

AVX2 inline __m256i perm(const int* table, __m256i i) {
    return _mm256_i32gather_epi32(table, _mm256_and_si256(i, _mm256_set1_epi32(255)), 4);
}

AVX2 inline __m256 select(__m256i condition, __m256 whenTrue, __m256 whenFalse) {
    return _mm256_blendv_ps(whenFalse, whenTrue, _mm256_castsi256_ps(condition));
}

AVX2 inline __m256 grad(__m256i hash, __m256 x, __m256 y, __m256 z) {
    const __m256i h = _mm256_and_si256(hash, _mm256_set1_epi32(15));
    const __m256 u = select(_mm256_cmpgt_epi32(_mm256_set1_epi32(8), h), x, y);
    const __m256i is12or14 = _mm256_or_si256(_mm256_cmpeq_epi32(h, _mm256_set1_epi32(12)),
                                             _mm256_cmpeq_epi32(h, _mm256_set1_epi32(14)));
    const __m256 v = select(_mm256_cmpgt_epi32(_mm256_set1_epi32(4), h), y, select(is12or14, x, z));
    const __m256 sign = splat(-0.0f);
    const __m256i bit1 = _mm256_cmpeq_epi32(_mm256_and_si256(h, _mm256_set1_epi32(1)), _mm256_setzero_si256());
    const __m256i bit2 = _mm256_cmpeq_epi32(_mm256_and_si256(h, _mm256_set1_epi32(2)), _mm256_setzero_si256());
    return add(select(bit1, u, _mm256_xor_ps(u, sign)), select(bit2, v, _mm256_xor_ps(v, sign)));
}

AVX2 inline __m256 isFinite(__m256 v) {
    // |v| < infinity is false for infinities and NaN.
    const __m256 magnitude = _mm256_andnot_ps(splat(-0.0f), v);
    return _mm256_cmp_ps(magnitude, splat(INFINITY), _CMP_LT_OQ);
}

AVX2 __m256 perlin3(const V3& p, const int* table, const int offsets[3]) {
    const __m256 finite = _mm256_and_ps(_mm256_and_ps(isFinite(p.x), isFinite(p.y)), isFinite(p.z));
    const __m256 fx = _mm256_floor_ps(p.x), fy = _mm256_floor_ps(p.y), fz = _mm256_floor_ps(p.z);
    const __m256i m255 = _mm256_set1_epi32(255);
    const __m256i X = _mm256_and_si256(_mm256_add_epi32(latticeIndex(fx), _mm256_set1_epi32(offsets[0])), m255);
    const __m256i Y = _mm256_and_si256(_mm256_add_epi32(latticeIndex(fy), _mm256_set1_epi32(offsets[1])), m255);
    const __m256i Z = _mm256_and_si256(_mm256_add_epi32(latticeIndex(fz), _mm256_set1_epi32(offsets[2])), m255);
    const __m256 x = sub(p.x, fx), y = sub(p.y, fy), z = sub(p.z, fz);
    const __m256 u = fade(x), v = fade(y), w = fade(z);
    const __m256i one = _mm256_set1_epi32(1);
    const __m256i A = _mm256_add_epi32(perm(table, X), Y);
    const __m256i AA = _mm256_add_epi32(perm(table, A), Z), AB = _mm256_add_epi32(perm(table, _mm256_add_epi32(A, one)), Z);
    const __m256i B = _mm256_add_epi32(perm(table, _mm256_add_epi32(X, one)), Y);
    const __m256i BA = _mm256_add_epi32(perm(table, B), Z), BB = _mm256_add_epi32(perm(table, _mm256_add_epi32(B, one)), Z);
    const __m256 x1 = sub(x, splat(1.0f)), y1 = sub(y, splat(1.0f)), z1 = sub(z, splat(1.0f));
    const __m256 l00 = lerp(u, grad(perm(table, AA), x, y, z), grad(perm(table, BA), x1, y, z));
    const __m256 l10 = lerp(u, grad(perm(table, AB), x, y1, z), grad(perm(table, BB), x1, y1, z));
    const __m256 l01 = lerp(u, grad(perm(table, _mm256_add_epi32(AA, one)), x, y, z1),
                            grad(perm(table, _mm256_add_epi32(BA, one)), x1, y, z1));
    const __m256 l11 = lerp(u, grad(perm(table, _mm256_add_epi32(AB, one)), x, y1, z1),
                            grad(perm(table, _mm256_add_epi32(BB, one)), x1, y1, z1));
    const __m256 result = lerp(w, lerp(v, l00, l10), lerp(v, l01, l11));
    return _mm256_blendv_ps(splat(noise::kNaN), result, finite);
}

AVX2 inline V3 offset(const V3& q, float d) { return {add(q.x, splat(d)), add(q.y, splat(d)), add(q.z, splat(d))}; }

// noise::warpedLayer: S(q + w (S(q + 50), S(q + 150), S(q + 250))), w = k F + D / (1 + k).
AVX2 __m256 warpedLayer(const V3& q, float k, float invOnePlusK, float warpLow, float warpHigh, const int* table,
                        const int offsets[3]) {
    const float w = k * warpHigh + warpLow * invOnePlusK;
    const __m256 ox = perlin3(offset(q, 50.0f), table, offsets);
    const __m256 oy = perlin3(offset(q, 150.0f), table, offsets);
    const __m256 oz = perlin3(offset(q, 250.0f), table, offsets);
    const __m256 ws = splat(w);
    return perlin3({add(q.x, mul(ws, ox)), add(q.y, mul(ws, oy)), add(q.z, mul(ws, oz))}, table, offsets);
}

AVX2 inline V3 scaled(const V3& p, float s) { return {mul(p.x, splat(s)), mul(p.y, splat(s)), mul(p.z, splat(s))}; }

AVX2 void warpedFbm8(const float* x, const float* y, const float* z, const float* amplitudeBase, float warpLow,
                     float warpHigh, const int* table, const int offsets[3], float* out) {
    const V3 p{_mm256_loadu_ps(x), _mm256_loadu_ps(y), _mm256_loadu_ps(z)};
    const __m256 a = _mm256_loadu_ps(amplitudeBase);
    __m256 sum = splat(0.0f), amplitude = splat(1.0f);
    sum = add(sum, mul(amplitude, warpedLayer(p, 0.0f, 1.0f, warpLow, warpHigh, table, offsets)));
    amplitude = mul(amplitude, a);
    sum = add(sum, mul(amplitude, warpedLayer(scaled(p, 2.0f), 1.0f, 0.5f, warpLow, warpHigh, table, offsets)));
    amplitude = mul(amplitude, a);
    sum = add(sum, mul(amplitude, warpedLayer(scaled(p, 4.0f), 2.0f, 0.333333343f, warpLow, warpHigh, table, offsets)));
    amplitude = mul(amplitude, a);
    sum = add(sum, mul(amplitude, warpedLayer(scaled(p, 8.0f), 3.0f, 0.25f, warpLow, warpHigh, table, offsets)));
    amplitude = mul(amplitude, a);
    sum = add(sum, mul(amplitude, warpedLayer(scaled(p, 16.0f), 4.0f, 0.2f, warpLow, warpHigh, table, offsets)));
    _mm256_storeu_ps(out, sum);
}

#undef AVX2

// The same for sixteen lanes where the CPU has AVX-512 (AVX512F only): the same operations in the
// same order, compares into mask registers, sign flips and magnitudes as integer bit operations.
#define AVX512 __attribute__((target("avx512f")))

struct V3x16 {
    __m512 x, y, z;
};

AVX512 inline __m512 add(__m512 a, __m512 b) { return _mm512_add_ps(a, b); }
AVX512 inline __m512 sub(__m512 a, __m512 b) { return _mm512_sub_ps(a, b); }
AVX512 inline __m512 mul(__m512 a, __m512 b) { return _mm512_mul_ps(a, b); }
AVX512 inline __m512 splat16(float v) { return _mm512_set1_ps(v); }

AVX512 inline __m512 fade(__m512 t) {
    return mul(mul(mul(t, t), t), add(mul(t, sub(mul(t, splat16(6.0f)), splat16(15.0f))), splat16(10.0f)));
}

AVX512 inline __m512 lerp(__m512 t, __m512 a, __m512 b) { return add(a, mul(t, sub(b, a))); }

AVX512 inline __m512i latticeIndex(__m512 floored) {
    const __m512 wrapped = sub(floored, mul(splat16(256.0f), _mm512_floor_ps(mul(floored, splat16(0.00390625f)))));
    return _mm512_maskz_cvttps_epi32(0xFFFF, wrapped); // (the unmasked form reads an undefined register)
}

AVX512 inline __m512i perm(const int* table, __m512i i) {
    return _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), 0xFFFF, _mm512_and_si512(i, _mm512_set1_epi32(255)),
                                       table, 4);
}

AVX512 inline __m512 flippedSign(__m512 v) {
    return _mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(v), _mm512_set1_epi32(int32_t(0x80000000u))));
}

AVX512 inline __m512 grad(__m512i hash, __m512 x, __m512 y, __m512 z) {
    const __m512i h = _mm512_and_si512(hash, _mm512_set1_epi32(15));
    const __m512 u = _mm512_mask_blend_ps(_mm512_cmplt_epi32_mask(h, _mm512_set1_epi32(8)), y, x);
    const __mmask16 is12or14 = _mm512_cmpeq_epi32_mask(h, _mm512_set1_epi32(12)) | _mm512_cmpeq_epi32_mask(h, _mm512_set1_epi32(14));
    const __m512 v = _mm512_mask_blend_ps(_mm512_cmplt_epi32_mask(h, _mm512_set1_epi32(4)),
                                          _mm512_mask_blend_ps(is12or14, z, x), y);
    const __mmask16 bit1 = _mm512_testn_epi32_mask(h, _mm512_set1_epi32(1));
    const __mmask16 bit2 = _mm512_testn_epi32_mask(h, _mm512_set1_epi32(2));
    return add(_mm512_mask_blend_ps(bit1, flippedSign(u), u), _mm512_mask_blend_ps(bit2, flippedSign(v), v));
}

AVX512 inline __mmask16 isFinite(__m512 v) {
    const __m512 magnitude =
        _mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(v), _mm512_set1_epi32(0x7fffffff)));
    return _mm512_cmp_ps_mask(magnitude, splat16(INFINITY), _CMP_LT_OQ);
}

AVX512 __m512 perlin3(const V3x16& p, const int* table, const int offsets[3]) {
    const __mmask16 finite = isFinite(p.x) & isFinite(p.y) & isFinite(p.z);
    const __m512 fx = _mm512_floor_ps(p.x), fy = _mm512_floor_ps(p.y), fz = _mm512_floor_ps(p.z);
    const __m512i m255 = _mm512_set1_epi32(255);
    const __m512i X = _mm512_and_si512(_mm512_add_epi32(latticeIndex(fx), _mm512_set1_epi32(offsets[0])), m255);
    const __m512i Y = _mm512_and_si512(_mm512_add_epi32(latticeIndex(fy), _mm512_set1_epi32(offsets[1])), m255);
    const __m512i Z = _mm512_and_si512(_mm512_add_epi32(latticeIndex(fz), _mm512_set1_epi32(offsets[2])), m255);
    const __m512 x = sub(p.x, fx), y = sub(p.y, fy), z = sub(p.z, fz);
    const __m512 u = fade(x), v = fade(y), w = fade(z);
    const __m512i one = _mm512_set1_epi32(1);
    const __m512i A = _mm512_add_epi32(perm(table, X), Y);
    const __m512i AA = _mm512_add_epi32(perm(table, A), Z), AB = _mm512_add_epi32(perm(table, _mm512_add_epi32(A, one)), Z);
    const __m512i B = _mm512_add_epi32(perm(table, _mm512_add_epi32(X, one)), Y);
    const __m512i BA = _mm512_add_epi32(perm(table, B), Z), BB = _mm512_add_epi32(perm(table, _mm512_add_epi32(B, one)), Z);
    const __m512 x1 = sub(x, splat16(1.0f)), y1 = sub(y, splat16(1.0f)), z1 = sub(z, splat16(1.0f));
    const __m512 l00 = lerp(u, grad(perm(table, AA), x, y, z), grad(perm(table, BA), x1, y, z));
    const __m512 l10 = lerp(u, grad(perm(table, AB), x, y1, z), grad(perm(table, BB), x1, y1, z));
    const __m512 l01 = lerp(u, grad(perm(table, _mm512_add_epi32(AA, one)), x, y, z1),
                            grad(perm(table, _mm512_add_epi32(BA, one)), x1, y, z1));
    const __m512 l11 = lerp(u, grad(perm(table, _mm512_add_epi32(AB, one)), x, y1, z1),
                            grad(perm(table, _mm512_add_epi32(BB, one)), x1, y1, z1));
    const __m512 result = lerp(w, lerp(v, l00, l10), lerp(v, l01, l11));
    return _mm512_mask_blend_ps(finite, splat16(noise::kNaN), result);
}

AVX512 inline V3x16 offset(const V3x16& q, float d) {
    return {add(q.x, splat16(d)), add(q.y, splat16(d)), add(q.z, splat16(d))};
}

AVX512 __m512 warpedLayer(const V3x16& q, float k, float invOnePlusK, float warpLow, float warpHigh, const int* table,
                          const int offsets[3]) {
    const float w = k * warpHigh + warpLow * invOnePlusK;
    const __m512 ox = perlin3(offset(q, 50.0f), table, offsets);
    const __m512 oy = perlin3(offset(q, 150.0f), table, offsets);
    const __m512 oz = perlin3(offset(q, 250.0f), table, offsets);
    const __m512 ws = splat16(w);
    return perlin3({add(q.x, mul(ws, ox)), add(q.y, mul(ws, oy)), add(q.z, mul(ws, oz))}, table, offsets);
}

AVX512 inline V3x16 scaled(const V3x16& p, float s) {
    return {mul(p.x, splat16(s)), mul(p.y, splat16(s)), mul(p.z, splat16(s))};
}

AVX512 void warpedFbm16(const float* x, const float* y, const float* z, const float* amplitudeBase, float warpLow,
                        float warpHigh, const int* table, const int offsets[3], float* out) {
    const V3x16 p{_mm512_loadu_ps(x), _mm512_loadu_ps(y), _mm512_loadu_ps(z)};
    const __m512 a = _mm512_loadu_ps(amplitudeBase);
    __m512 sum = splat16(0.0f), amplitude = splat16(1.0f);
    sum = add(sum, mul(amplitude, warpedLayer(p, 0.0f, 1.0f, warpLow, warpHigh, table, offsets)));
    amplitude = mul(amplitude, a);
    sum = add(sum, mul(amplitude, warpedLayer(scaled(p, 2.0f), 1.0f, 0.5f, warpLow, warpHigh, table, offsets)));
    amplitude = mul(amplitude, a);
    sum = add(sum, mul(amplitude, warpedLayer(scaled(p, 4.0f), 2.0f, 0.333333343f, warpLow, warpHigh, table, offsets)));
    amplitude = mul(amplitude, a);
    sum = add(sum, mul(amplitude, warpedLayer(scaled(p, 8.0f), 3.0f, 0.25f, warpLow, warpHigh, table, offsets)));
    amplitude = mul(amplitude, a);
    sum = add(sum, mul(amplitude, warpedLayer(scaled(p, 16.0f), 4.0f, 0.2f, warpLow, warpHigh, table, offsets)));
    _mm512_storeu_ps(out, sum);
}

#undef AVX512
#endif

} // namespace

void warpedFbmBatch(const float* x, const float* y, const float* z, const float* roughness, float warpLow,
                    float warpHigh, uint32_t seed, size_t n, float* out) {
    size_t i = 0;
#ifdef VOXC_NOISE_AVX2
    static const bool avx2 = __builtin_cpu_supports("avx2");
    static const bool avx512 = __builtin_cpu_supports("avx512f");
    if (avx2) {
        const int* table = perlinPermutation().data();
        const int offsets[3] = {noise::seedOffset(seed, 0), noise::seedOffset(seed, 1), noise::seedOffset(seed, 2)};
        if (avx512)
            for (; i + 16 <= n; i += 16) {
                float base[16];
                for (int lane = 0; lane < 16; ++lane) base[lane] = std::exp2(-(1.0f - roughness[i + size_t(lane)]));
                warpedFbm16(x + i, y + i, z + i, base, warpLow, warpHigh, table, offsets, out + i);
            }
        for (; i + 8 <= n; i += 8) {
            // The layer amplitude's base 2^-(1 - R), by the scalar exp2 (libm's, as warpedFbm's).
            float base[8];
            for (int lane = 0; lane < 8; ++lane) base[lane] = std::exp2(-(1.0f - roughness[i + size_t(lane)]));
            warpedFbm8(x + i, y + i, z + i, base, warpLow, warpHigh, table, offsets, out + i);
        }
        if (i < n) {
            // The last 1-7 points in one register too, padded with copies of the last one (lanes
            // are independent): the scalar code took as long per point as the register for
            // eight, and the curves' displacement batches are rows of a few dozen points.
            float px[8], py[8], pz[8], base[8], result[8];
            for (size_t lane = 0; lane < 8; ++lane) {
                const size_t j = std::min(i + lane, n - 1);
                px[lane] = x[j], py[lane] = y[j], pz[lane] = z[j];
                base[lane] = std::exp2(-(1.0f - roughness[j]));
            }
            warpedFbm8(px, py, pz, base, warpLow, warpHigh, table, offsets, result);
            for (size_t lane = 0; i + lane < n; ++lane) out[i + lane] = result[lane];
            i = n;
        }
    }
#endif
    for (; i < n; ++i) out[i] = noise::warpedFbm({x[i], y[i], z[i]}, roughness[i], warpLow, warpHigh, seed);
}

} // namespace voxc
