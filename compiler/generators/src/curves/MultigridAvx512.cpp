#include "MultigridAvx512.h"

#ifdef VOXC_COLOUR_KERNEL
#include "voxc/core/Simd.h"
#include "voxc/generators/curves/Multigrid.h"

#include <immintrin.h>

#include <algorithm>

namespace voxc::curves {
namespace {

#define VOXC_AVX512 __attribute__((target("avx512f,avx512bw,avx512dq,avx512vl")))

// One row of a colour's half sweep: its rows, weights and lane constants.
struct ColourRow {
    float* u;
    const float *ym, *yp, *zm, *zp, *rhs;
    const uint8_t* fixed;
    int32_t n;
    __m512 vwx, vwy, vwz, vomega, vweights, vendWeights;
    __m512i even, odd, spreadLow, spreadHigh;
};

// Row y of the slice into `r` (a ColourRow or a ResidualRow): its values, its fixed flags and its
// four y/z neighbour rows, a missing one being `absent`, or the row itself where absent is null.
template <class Row> VOXC_AVX512 inline void loadRow(Row& r, const SliceRows& s, int32_t y, const float* absent) {
    const size_t offset = size_t(y) * size_t(s.n);
    r.u = s.u + offset;
    if (!absent) absent = r.u;
    r.ym = y > 0 ? r.u - s.n : absent;
    r.yp = y + 1 < s.rows ? r.u + s.n : absent;
    r.zm = s.below ? s.below + offset : absent;
    r.zp = s.above ? s.above + offset : absent;
    r.fixed = s.fixed + offset;
}

// 16 floats from p, those outside the row (clear in `inRow`) read as +0: a plain load where the
// whole block lies inside it.
template <bool full>
VOXC_AVX512 __attribute__((always_inline)) inline __m512 lanes(const float* p, __mmask16 inRow) {
    if constexpr (full) return _mm512_loadu_ps(p);
    else return _mm512_maskz_loadu_ps(inRow, p);
}

// The even columns of the 32 from p + x0: the colour's cells, or their y/z neighbours in a row of p.
template <bool full>
VOXC_AVX512 __attribute__((always_inline)) inline __m512 colourLanes(__mmask16 low, __mmask16 high, __m512i even,
                                                                      const float* p, int32_t x0) {
    return _mm512_permutex2var_ps(lanes<full>(p + x0, low), even, lanes<full>(p + x0 + 16, high));
}

// The block of 32 columns from x0 (16 cells of the colour, x = x0 + 2k), `before` holding the -x
// neighbour of its first cell in lane 15 (the block before's +x neighbours). `full`: the block
// lies inside the row and holds neither end cell (x0 > 0, x0 + 32 <= n - 1), so its loads need
// no masks and every lane divides by the interior weights: the same values as the masked form.
template <bool finest, bool full>
VOXC_AVX512 __attribute__((always_inline)) inline void relaxBlock(const ColourRow& r, int32_t x0, __m512& before) {
    const int32_t n = r.n;
    const int32_t left = n - x0; // columns from x0 to the row's end
    const __mmask32 inRow = full || left >= 32 ? ~__mmask32(0) : __mmask32((uint32_t(1) << left) - 1);
    const __mmask16 low = __mmask16(inRow), high = __mmask16(inRow >> 16);
    const __m512 a = lanes<full>(r.u + x0, low), b = lanes<full>(r.u + x0 + 16, high);
    const __m512 centre = _mm512_permutex2var_ps(a, r.even, b);
    const __m512 right = _mm512_permutex2var_ps(a, r.odd, b); // +0 past the row's end
    // (The maskz forms with every lane set: GCC 12's plain forms warn of their undefined source.)
    const __m512 leftN = _mm512_castsi512_ps(
        _mm512_maskz_alignr_epi32(0xffff, _mm512_castps_si512(right), _mm512_castps_si512(before), 15));
    before = right;
    __m512 sum = _mm512_setzero_ps();
    if constexpr (finest) {
        sum = _mm512_add_ps(sum, leftN);
        sum = _mm512_add_ps(sum, right);
        sum = _mm512_add_ps(sum, colourLanes<full>(low, high, r.even, r.ym, x0));
        sum = _mm512_add_ps(sum, colourLanes<full>(low, high, r.even, r.yp, x0));
        sum = _mm512_add_ps(sum, colourLanes<full>(low, high, r.even, r.zm, x0));
        sum = _mm512_add_ps(sum, colourLanes<full>(low, high, r.even, r.zp, x0));
    } else {
        sum = _mm512_add_ps(sum, _mm512_mul_ps(r.vwx, leftN));
        sum = _mm512_add_ps(sum, _mm512_mul_ps(r.vwx, right));
        sum = _mm512_add_ps(sum, _mm512_mul_ps(r.vwy, colourLanes<full>(low, high, r.even, r.ym, x0)));
        sum = _mm512_add_ps(sum, _mm512_mul_ps(r.vwy, colourLanes<full>(low, high, r.even, r.yp, x0)));
        sum = _mm512_add_ps(sum, _mm512_mul_ps(r.vwz, colourLanes<full>(low, high, r.even, r.zm, x0)));
        sum = _mm512_add_ps(sum, _mm512_mul_ps(r.vwz, colourLanes<full>(low, high, r.even, r.zp, x0)));
        sum = _mm512_sub_ps(sum, colourLanes<full>(low, high, r.even, r.rhs, x0));
    }
    // Lane k holds x = x0 + 2k: the end cells are x = 0 (lane 0 of the first block) and x = n - 1.
    __m512 divisor = r.vweights;
    if constexpr (!full) {
        __mmask16 ends = x0 == 0 ? __mmask16(1) : __mmask16(0);
        if (((n - 1 - x0) & 1) == 0 && n - 1 - x0 < 32) ends |= __mmask16(1u << ((n - 1 - x0) >> 1));
        divisor = _mm512_mask_blend_ps(ends, r.vweights, r.vendWeights);
    }
    const __m512 relaxed = _mm512_div_ps(sum, divisor);
    const __m512 next = _mm512_add_ps(centre, _mm512_mul_ps(r.vomega, _mm512_sub_ps(relaxed, centre)));
    // The colour's free cells among the row's columns from x0.
    const __m256i f = full ? _mm256_loadu_si256(reinterpret_cast<const __m256i*>(r.fixed + x0))
                           : _mm256_maskz_loadu_epi8(inRow, r.fixed + x0);
    const __mmask32 store = _mm256_cmpeq_epi8_mask(f, _mm256_setzero_si256()) & inRow & __mmask32(0x55555555u);
    _mm512_mask_storeu_ps(r.u + x0, __mmask16(store), _mm512_maskz_permutexvar_ps(0xffff, r.spreadLow, next));
    _mm512_mask_storeu_ps(r.u + x0 + 16, __mmask16(store >> 16), _mm512_maskz_permutexvar_ps(0xffff, r.spreadHigh, next));
}

template <bool finest>
VOXC_AVX512 void relaxKernel(const SliceRows& s) {
    const int32_t n = s.n;
    ColourRow r{};
    r.n = n;
    r.even = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
    r.odd = _mm512_setr_epi32(1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31);
    r.spreadLow = _mm512_setr_epi32(0, 0, 1, 0, 2, 0, 3, 0, 4, 0, 5, 0, 6, 0, 7, 0);
    r.spreadHigh = _mm512_setr_epi32(8, 0, 9, 0, 10, 0, 11, 0, 12, 0, 13, 0, 14, 0, 15, 0);
    r.vwx = _mm512_set1_ps(s.wx), r.vwy = _mm512_set1_ps(s.wy), r.vwz = _mm512_set1_ps(s.wz);
    r.vomega = _mm512_set1_ps(kOverRelaxation);
    for (int32_t y = 0; y < s.rows; ++y) {
        loadRow(r, s, y, s.zeros); // a missing neighbour adds an exact +0
        r.rhs = s.rhs ? s.rhs + size_t(y) * size_t(n) : s.zeros;
        // Sums of the present neighbours' weights from 0 in neighbour order: an interior cell's
        // (both x neighbours) and an end cell's (one).
        float weights = 0.0f, endWeights = 0.0f;
        weights += s.wx, weights += s.wx;
        endWeights += s.wx;
        if (y > 0) weights += s.wy, endWeights += s.wy;
        if (y + 1 < s.rows) weights += s.wy, endWeights += s.wy;
        if (s.below) weights += s.wz, endWeights += s.wz;
        if (s.above) weights += s.wz, endWeights += s.wz;
        r.vweights = _mm512_set1_ps(weights), r.vendWeights = _mm512_set1_ps(endWeights);
        const int32_t xs = (s.firstParity + y) & 1; // (x + parity) even
        // Lane 15: the -x neighbour of the block's first cell (+0 at x = 0).
        __m512 before = xs > 0 ? _mm512_set1_ps(r.u[xs - 1]) : _mm512_setzero_ps();
        int32_t x0 = xs;
        if (x0 == 0) relaxBlock<finest, false>(r, x0, before), x0 += 32;
        for (; x0 + 32 <= n - 1; x0 += 32) relaxBlock<finest, true>(r, x0, before);
        for (; x0 < n; x0 += 32) relaxBlock<finest, false>(r, x0, before);
    }
}

// One row's rows for maxResidualKernel (a missing neighbour row is the row itself).
struct ResidualRow {
    const float *u, *ym, *yp, *zm, *zp;
    const uint8_t* fixed;
    int32_t n;
    __m512 vwx, vwy, vwz;
};

// max(most, |r|) over the free cells of the 16 columns from x0. `full`: both x neighbours of
// every column lie in the row (x0 > 0, x0 + 16 < n), so no load needs a mask: the same values as
// the masked form.
template <bool finest, bool full>
VOXC_AVX512 __attribute__((always_inline)) inline __m512 residualBlock(const ResidualRow& r, int32_t x0, __m512 most) {
    const int32_t left = r.n - x0;
    const __mmask16 inRow = full || left >= 16 ? __mmask16(0xffff) : __mmask16((1u << left) - 1);
    __m512 c, l, rt, ym, yp, zm, zp;
    __mmask16 free;
    if constexpr (full) {
        c = _mm512_loadu_ps(r.u + x0), l = _mm512_loadu_ps(r.u + x0 - 1), rt = _mm512_loadu_ps(r.u + x0 + 1);
        ym = _mm512_loadu_ps(r.ym + x0), yp = _mm512_loadu_ps(r.yp + x0);
        zm = _mm512_loadu_ps(r.zm + x0), zp = _mm512_loadu_ps(r.zp + x0);
        free = _mm_cmpeq_epi8_mask(_mm_loadu_si128(reinterpret_cast<const __m128i*>(r.fixed + x0)), _mm_setzero_si128());
    } else {
        const __mmask16 hasLeft = x0 == 0 ? __mmask16(inRow & ~1u) : inRow;
        const __mmask16 hasRight = left > 16 ? inRow : __mmask16(inRow >> 1);
        c = _mm512_maskz_loadu_ps(inRow, r.u + x0);
        l = _mm512_mask_loadu_ps(c, hasLeft, r.u + x0 - 1);
        rt = _mm512_mask_loadu_ps(c, hasRight, r.u + x0 + 1);
        ym = _mm512_mask_loadu_ps(c, inRow, r.ym + x0), yp = _mm512_mask_loadu_ps(c, inRow, r.yp + x0);
        zm = _mm512_mask_loadu_ps(c, inRow, r.zm + x0), zp = _mm512_mask_loadu_ps(c, inRow, r.zp + x0);
        free = _mm_mask_cmpeq_epi8_mask(inRow, _mm_maskz_loadu_epi8(inRow, r.fixed + x0), _mm_setzero_si128());
    }
    const __m512 terms[6] = {_mm512_sub_ps(l, c),  _mm512_sub_ps(rt, c), _mm512_sub_ps(ym, c),
                             _mm512_sub_ps(yp, c), _mm512_sub_ps(zm, c), _mm512_sub_ps(zp, c)};
    __m512 lap = _mm512_setzero_ps();
    for (int32_t k = 0; k < 6; ++k) {
        if constexpr (finest) {
            lap = _mm512_add_ps(lap, terms[k]);
        } else {
            const __m512 w = k < 2 ? r.vwx : k < 4 ? r.vwy : r.vwz;
            lap = _mm512_add_ps(lap, _mm512_mul_ps(w, terms[k]));
        }
    }
    const __m512 residual = _mm512_sub_ps(_mm512_setzero_ps(), lap);
    return _mm512_mask_max_ps(most, free, _mm512_abs_ps(residual), most);
}

template <bool finest>
VOXC_AVX512 float maxResidualKernel(const SliceRows& s, float worst) {
    const int32_t n = s.n;
    ResidualRow r{};
    r.n = n;
    r.vwx = _mm512_set1_ps(s.wx), r.vwy = _mm512_set1_ps(s.wy), r.vwz = _mm512_set1_ps(s.wz);
    __m512 most = _mm512_set1_ps(worst);
    for (int32_t y = 0; y < s.rows; ++y) {
        loadRow(r, s, y, nullptr); // a missing neighbour is the row itself: u_i - u_i = +0
        most = residualBlock<finest, false>(r, 0, most);
        int32_t x0 = 16;
        for (; x0 + 16 < n; x0 += 16) most = residualBlock<finest, true>(r, x0, most);
        for (; x0 < n; x0 += 16) most = residualBlock<finest, false>(r, x0, most);
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
