#include "MultigridAvx512.h"

#ifdef VOXC_COLOUR_KERNEL
#include "voxc/core/Simd.h"
#include "voxc/generators/curves/Multigrid.h"

#include <immintrin.h>

#include <algorithm>

namespace voxc::curves {
namespace {

template <bool finest>
__attribute__((target("avx512f,avx512bw,avx512dq,avx512vl"))) void relaxKernel(const SliceRows& s) {
    const int32_t n = s.n;
    const __m512i even = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
    const __m512i odd = _mm512_setr_epi32(1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31);
    const __m512i spreadLow = _mm512_setr_epi32(0, 0, 1, 0, 2, 0, 3, 0, 4, 0, 5, 0, 6, 0, 7, 0);
    const __m512i spreadHigh = _mm512_setr_epi32(8, 0, 9, 0, 10, 0, 11, 0, 12, 0, 13, 0, 14, 0, 15, 0);
    const __m512 vwx = _mm512_set1_ps(s.wx), vwy = _mm512_set1_ps(s.wy), vwz = _mm512_set1_ps(s.wz);
    const __m512 vomega = _mm512_set1_ps(kOverRelaxation);
    for (int32_t y = 0; y < s.rows; ++y) {
        const size_t offset = size_t(y) * size_t(n);
        float* u = s.u + offset;
        const float* ym = y > 0 ? u - n : s.zeros;
        const float* yp = y + 1 < s.rows ? u + n : s.zeros;
        const float* zm = s.below ? s.below + offset : s.zeros;
        const float* zp = s.above ? s.above + offset : s.zeros;
        const float* rhs = s.rhs ? s.rhs + offset : s.zeros;
        const uint8_t* fixed = s.fixed + offset;
        // Sums of the present neighbours' weights from 0 in neighbour order: an interior cell's
        // (both x neighbours) and an end cell's (one).
        float weights = 0.0f, endWeights = 0.0f;
        weights += s.wx, weights += s.wx;
        endWeights += s.wx;
        if (y > 0) weights += s.wy, endWeights += s.wy;
        if (y + 1 < s.rows) weights += s.wy, endWeights += s.wy;
        if (s.below) weights += s.wz, endWeights += s.wz;
        if (s.above) weights += s.wz, endWeights += s.wz;
        const __m512 vweights = _mm512_set1_ps(weights), vendWeights = _mm512_set1_ps(endWeights);
        const int32_t xs = (s.firstParity + y) & 1; // (x + parity) even
        // Lane 15: the -x neighbour of the block's first cell (+0 at x = 0).
        __m512 before = xs > 0 ? _mm512_set1_ps(u[xs - 1]) : _mm512_setzero_ps();
        for (int32_t x0 = xs; x0 < n; x0 += 32) {
            const int32_t left = n - x0; // columns from x0 to the row's end
            const __mmask32 inRow = left >= 32 ? ~__mmask32(0) : __mmask32((uint32_t(1) << left) - 1);
            const __mmask16 low = __mmask16(inRow), high = __mmask16(inRow >> 16);
#define VOXC_COLOUR_LANES(p) \
    _mm512_permutex2var_ps(_mm512_maskz_loadu_ps(low, (p) + x0), even, _mm512_maskz_loadu_ps(high, (p) + x0 + 16))
            const __m512 a = _mm512_maskz_loadu_ps(low, u + x0), b = _mm512_maskz_loadu_ps(high, u + x0 + 16);
            const __m512 centre = _mm512_permutex2var_ps(a, even, b);
            const __m512 right = _mm512_permutex2var_ps(a, odd, b); // +0 past the row's end
            // (The maskz forms with every lane set: GCC 12's plain forms warn of their undefined source.)
            const __m512 leftN = _mm512_castsi512_ps(
                _mm512_maskz_alignr_epi32(0xffff, _mm512_castps_si512(right), _mm512_castps_si512(before), 15));
            before = right;
            __m512 sum = _mm512_setzero_ps();
            if constexpr (finest) {
                sum = _mm512_add_ps(sum, leftN);
                sum = _mm512_add_ps(sum, right);
                sum = _mm512_add_ps(sum, VOXC_COLOUR_LANES(ym));
                sum = _mm512_add_ps(sum, VOXC_COLOUR_LANES(yp));
                sum = _mm512_add_ps(sum, VOXC_COLOUR_LANES(zm));
                sum = _mm512_add_ps(sum, VOXC_COLOUR_LANES(zp));
            } else {
                sum = _mm512_add_ps(sum, _mm512_mul_ps(vwx, leftN));
                sum = _mm512_add_ps(sum, _mm512_mul_ps(vwx, right));
                sum = _mm512_add_ps(sum, _mm512_mul_ps(vwy, VOXC_COLOUR_LANES(ym)));
                sum = _mm512_add_ps(sum, _mm512_mul_ps(vwy, VOXC_COLOUR_LANES(yp)));
                sum = _mm512_add_ps(sum, _mm512_mul_ps(vwz, VOXC_COLOUR_LANES(zm)));
                sum = _mm512_add_ps(sum, _mm512_mul_ps(vwz, VOXC_COLOUR_LANES(zp)));
                sum = _mm512_sub_ps(sum, VOXC_COLOUR_LANES(rhs));
            }
#undef VOXC_COLOUR_LANES
            // Lane k holds x = x0 + 2k: the end cells are x = 0 (lane 0 of the first block) and
            // x = n - 1.
            __mmask16 ends = x0 == 0 ? __mmask16(1) : __mmask16(0);
            if (((n - 1 - x0) & 1) == 0 && n - 1 - x0 < 32) ends |= __mmask16(1u << ((n - 1 - x0) >> 1));
            const __m512 divisor = _mm512_mask_blend_ps(ends, vweights, vendWeights);
            const __m512 relaxed = _mm512_div_ps(sum, divisor);
            const __m512 next = _mm512_add_ps(centre, _mm512_mul_ps(vomega, _mm512_sub_ps(relaxed, centre)));
            // The colour's free cells among the row's columns from x0.
            const __m256i f = _mm256_maskz_loadu_epi8(inRow, fixed + x0);
            const __mmask32 store = _mm256_cmpeq_epi8_mask(f, _mm256_setzero_si256()) & inRow & __mmask32(0x55555555u);
            _mm512_mask_storeu_ps(u + x0, __mmask16(store), _mm512_maskz_permutexvar_ps(0xffff, spreadLow, next));
            _mm512_mask_storeu_ps(u + x0 + 16, __mmask16(store >> 16), _mm512_maskz_permutexvar_ps(0xffff, spreadHigh, next));
        }
    }
}

template <bool finest>
__attribute__((target("avx512f,avx512bw,avx512dq,avx512vl"))) float maxResidualKernel(const SliceRows& s,
                                                                                         float worst) {
    const int32_t n = s.n;
    const __m512 vwx = _mm512_set1_ps(s.wx), vwy = _mm512_set1_ps(s.wy), vwz = _mm512_set1_ps(s.wz);
    __m512 most = _mm512_set1_ps(worst);
    for (int32_t y = 0; y < s.rows; ++y) {
        const size_t offset = size_t(y) * size_t(n);
        const float* u = s.u + offset;
        const float* ym = y > 0 ? u - n : u;
        const float* yp = y + 1 < s.rows ? u + n : u;
        const float* zm = s.below ? s.below + offset : u;
        const float* zp = s.above ? s.above + offset : u;
        const uint8_t* fixed = s.fixed + offset;
        for (int32_t x0 = 0; x0 < n; x0 += 16) {
            const int32_t left = n - x0;
            const __mmask16 inRow = left >= 16 ? __mmask16(0xffff) : __mmask16((1u << left) - 1);
            const __mmask16 hasLeft = x0 == 0 ? __mmask16(inRow & ~1u) : inRow;
            const __mmask16 hasRight = left > 16 ? inRow : __mmask16(inRow >> 1);
            const __m512 c = _mm512_maskz_loadu_ps(inRow, u + x0);
            const __m512 l = _mm512_mask_loadu_ps(c, hasLeft, u + x0 - 1);
            const __m512 r = _mm512_mask_loadu_ps(c, hasRight, u + x0 + 1);
            const __m512 terms[6] = {
                _mm512_sub_ps(l, c),
                _mm512_sub_ps(r, c),
                _mm512_sub_ps(_mm512_mask_loadu_ps(c, inRow, ym + x0), c),
                _mm512_sub_ps(_mm512_mask_loadu_ps(c, inRow, yp + x0), c),
                _mm512_sub_ps(_mm512_mask_loadu_ps(c, inRow, zm + x0), c),
                _mm512_sub_ps(_mm512_mask_loadu_ps(c, inRow, zp + x0), c),
            };
            __m512 lap = _mm512_setzero_ps();
            for (int32_t k = 0; k < 6; ++k) {
                if constexpr (finest) {
                    lap = _mm512_add_ps(lap, terms[k]);
                } else {
                    const __m512 w = k < 2 ? vwx : k < 4 ? vwy : vwz;
                    lap = _mm512_add_ps(lap, _mm512_mul_ps(w, terms[k]));
                }
            }
            const __m512 residual = _mm512_sub_ps(_mm512_setzero_ps(), lap);
            const __mmask16 free =
                _mm_mask_cmpeq_epi8_mask(inRow, _mm_maskz_loadu_epi8(inRow, fixed + x0), _mm_setzero_si128());
            most = _mm512_mask_max_ps(most, free, _mm512_abs_ps(residual), most);
        }
    }
    float lanes[16];
    _mm512_storeu_ps(lanes, most);
    for (const float lane : lanes) worst = std::max(worst, lane);
    return worst;
}

} // namespace

bool hasColourKernel() { return hostSimd() == Simd::Avx512; }

void relaxColourSliceAvx512(const SliceRows& s, bool finest) {
    if (finest) relaxKernel<true>(s);
    else relaxKernel<false>(s);
}

float maxResidualSliceAvx512(const SliceRows& s, bool finest, float worst) {
    return finest ? maxResidualKernel<true>(s, worst) : maxResidualKernel<false>(s, worst);
}

} // namespace voxc::curves
#endif
