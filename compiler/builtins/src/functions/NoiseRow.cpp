#include "voxc/builtins/NoiseRow.h"

#include "Noise.h"
#include "NoiseCommon.h"
#include "NoiseLanes.h"
#include "voxc/core/Simd.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#define VOXC_NOISE_ROW_AVX512 1 // and AVX2
#endif

namespace voxc {

namespace {

using OctaveTerm = FractalRow::OctaveTerm;

// A lattice x's four (y, z) corners in the table, in perlin3's order of use: (y, z), (y + 1, z),
// (y, z + 1), (y + 1, z + 1) (its AA, AB, AA + 1 and AB + 1 hashes).
constexpr size_t kCorners = 4;
// Table entries past the last cell that a sixteen-point load may read (their values are unused).
constexpr size_t kTablePadding = 17;
// A row whose points span more lattice cells than this many per point (a huge frequency) is
// evaluated point by point: its table would cost more than the points.
constexpr float kMaxCellsPerPoint = 2.0f;
// Lattice floors below 2^24 in magnitude subtract exactly, so a point's cell is floor - lo.
constexpr float kExactFloors = 16777216.0f;

// noise::grad(hash, x, y, z) with y and z fixed, split as part + x * coefficient: at most one of
// grad's u, v is x, so the gradient is part + (+-x) (IEEE addition commutes; x * +-1 is +-x) or,
// without x, the part itself, which part + x * (-0 or +0) also is when the zero's sign makes
// x * 0 equal -0: -0 for the low corners' x in [0, 1), +0 for the high corners' x - 1 in [-1, 0)
// (and part + -0 is part, signed zeros included). noise_column.glsl splits it the same way along y.
constexpr float gradientPart(int hash, float y, float z) {
    const int h = hash & 15;
    if (h < 4) return (h & 2) ? -y : y;                    // u = x, v = y
    if (h < 8) return (h & 2) ? -z : z;                    // u = x, v = z
    if (h == 12 || h == 14) return (h & 1) ? -y : y;       // u = y, v = x
    return ((h & 1) ? -y : y) + ((h & 2) ? -z : z);        // u = y, v = z
}

// The coefficient of x for hash h at a low (x in [0, 1)) or high (x - 1) lattice corner: grad's
// value at x = 1, y = z = 0 (+-1 where it takes x), the zero of the right sign where it does not.
constexpr float xCoefficient(int h, bool high) {
    const float g = noise::grad(h, 1.0f, 0.0f, 0.0f);
    return g != 0.0f ? g : high ? 0.0f : -0.0f;
}

constexpr std::array<std::array<float, 16>, 2> kXCoefficients = [] {
    std::array<std::array<float, 16>, 2> table{};
    for (int h = 0; h < 16; ++h) table[0][size_t(h)] = xCoefficient(h, false), table[1][size_t(h)] = xCoefficient(h, true);
    return table;
}();

// One octave's lattice along the row: per corner c and lattice x = lo + j, at [c * stride + j],
// the gradients' parts and x coefficients (as a low and as a high corner); the y, z fades.
struct RowLattice {
    const float* parts;
    const float* lowCoefficients;
    const float* highCoefficients;
    size_t stride;
    float lo; // the floor of the row's lowest finite point
    float v, w;
};

// perlin3 of a point with x fraction x in the cell of lattice x = lo + j.
float perlinAt(const RowLattice& l, size_t j, float x) {
    const float x1 = x - 1.0f, u = noise::fade(x);
    float corner[kCorners];
    for (size_t c = 0; c < kCorners; ++c) {
        const size_t at = c * l.stride + j;
        corner[c] = noise::lerp(u, l.parts[at] + x * l.lowCoefficients[at], l.parts[at + 1] + x1 * l.highCoefficients[at + 1]);
    }
    return noise::lerp(l.w, noise::lerp(l.v, corner[0], corner[1]), noise::lerp(l.v, corner[2], corner[3]));
}

// An octave's noise n at a point into the fractal's sum: `out` = amplitude * n (Sum) or
// amplitude * |n| (Absolute) on the first octave, out + that after; or n itself (`store`).
void addTerm(float n, OctaveTerm term, float& out) {
    if (term.store) {
        out = n;
        return;
    }
    const float weighted = term.amplitude * (term.fold == FractalFold::Absolute ? std::fabs(n) : n);
    out = term.first ? weighted : out + weighted;
}

float perlinAtPoint(const RowLattice& l, float qx) {
    if (!std::isfinite(qx)) return noise::kNaN;
    const float fx = std::floor(qx);
    return perlinAt(l, size_t(fx - l.lo), qx - fx);
}

// scaled[i] = x[i] * frequency; the lowest and highest floor among the finite ones, and whether
// all are finite.
void scaleRow(const float* x, float frequency, size_t n, float* scaled, float& lo, float& hi, bool& allFinite) {
    lo = INFINITY, hi = -INFINITY, allFinite = true;
    for (size_t i = 0; i < n; ++i) {
        scaled[i] = x[i] * frequency;
        if (std::isfinite(scaled[i])) {
            const float fx = std::floor(scaled[i]);
            lo = std::min(lo, fx);
            hi = std::max(hi, fx);
        } else {
            allFinite = false;
        }
    }
}

// RowHashes' tables for lattice x = X0 + j, j < entries, with y Y and z Z: each corner's hash and
// the coefficients of x that go with it.
void makeRowHashes(int X0, int Y, int Z, size_t entries, size_t stride, int32_t* hashes, float* lowCoefficients,
                   float* highCoefficients) {
    const int* perm = perlinPermutation().data();
    for (size_t j = 0; j < entries; ++j) {
        // perlin3's A = perm(X) + Y for X = lattice x, then AA, AB and their + 1 neighbours.
        const int A = perm[(X0 + int(j)) & 255] + Y;
        const int AA = perm[A & 255] + Z, AB = perm[(A + 1) & 255] + Z;
        const int corners[kCorners] = {perm[AA & 255], perm[AB & 255], perm[(AA + 1) & 255], perm[(AB + 1) & 255]};
        for (size_t c = 0; c < kCorners; ++c) {
            const int hash = corners[c] & 15;
            hashes[c * stride + j] = hash;
            lowCoefficients[c * stride + j] = kXCoefficients[0][size_t(hash)];
            highCoefficients[c * stride + j] = kXCoefficients[1][size_t(hash)];
        }
    }
}

#ifdef VOXC_NOISE_ROW_AVX512
#define LANES __attribute__((target("avx512f")))

namespace rowLanes16 {

using namespace noise::simd16; // Floats, add, sub, mul, splat, floorOf
using Ints = __m512i;
using Active = __mmask16;
constexpr size_t kLanes = 16;

LANES inline Floats magnitude(Floats v) {
    return _mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(v), _mm512_set1_epi32(0x7fffffff)));
}
LANES inline Active activeLanes(size_t count) { return count >= 16 ? Active(0xFFFF) : Active((1u << count) - 1u); }
LANES inline Floats loadActive(Active active, const float* from) { return _mm512_maskz_loadu_ps(active, from); }
LANES inline void storeActive(float* to, Active active, Floats v) { _mm512_mask_storeu_ps(to, active, v); }
LANES inline Active finiteAmong(Active active, Floats v) {
    return _mm512_mask_cmp_ps_mask(active, magnitude(v), splat(INFINITY), _CMP_LT_OQ);
}
LANES inline Floats select(Active where, Floats otherwise, Floats v) { return _mm512_mask_blend_ps(where, otherwise, v); }
// (the unmasked conversion and permutes read an undefined register)
LANES inline Ints truncate(Floats v) { return _mm512_maskz_cvttps_epi32(0xFFFF, v); }
LANES inline Ints minus(Ints a, int32_t b) { return _mm512_sub_epi32(a, _mm512_set1_epi32(b)); }
LANES inline bool anyOutside(Active active, Ints idx) { return _mm512_mask_cmpgt_epu32_mask(active, idx, _mm512_set1_epi32(15)) != 0; }
LANES inline bool allZero(Ints idx) { return _mm512_test_epi32_mask(idx, idx) == 0; }
LANES inline Floats permuted(const float* table, Ints idx) {
    return _mm512_maskz_permutexvar_ps(0xFFFF, idx, _mm512_loadu_ps(table));
}

#include "NoiseRowLanes.inc"

constexpr int32_t kSignBit = int32_t(0x80000000u);

// gradientPart(h, y, z) for the sixteen hashes h: what each takes of y and z, and their signs.
struct PartRecipe {
    int32_t ySign[16], zSign[16];
    __mmask16 usesY, usesZ;
};

// From gradientPart itself: with y = 1 and z = 0 its value is +-1 where it takes y (+-0 where
// not), and likewise for z.
constexpr PartRecipe partRecipe() {
    PartRecipe r{};
    for (int h = 0; h < 16; ++h) {
        const float y = gradientPart(h, 1.0f, 0.0f), z = gradientPart(h, 0.0f, 1.0f);
        r.ySign[h] = y < 0.0f ? kSignBit : 0;
        r.zSign[h] = z < 0.0f ? kSignBit : 0;
        r.usesY = __mmask16(r.usesY | (y != 0.0f ? 1 << h : 0));
        r.usesZ = __mmask16(r.usesZ | (z != 0.0f ? 1 << h : 0));
    }
    return r;
}

LANES void partsOfHashes16(float y, float z, float* out) {
    static constexpr PartRecipe r = partRecipe();
    const __m512 ys = _mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(_mm512_set1_ps(y)), _mm512_loadu_si512(r.ySign)));
    const __m512 zs = _mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(_mm512_set1_ps(z)), _mm512_loadu_si512(r.zSign)));
    const __m512 one = _mm512_mask_blend_ps(r.usesY, zs, ys);
    _mm512_storeu_ps(out, _mm512_mask_blend_ps(__mmask16(r.usesY & r.usesZ), one, _mm512_add_ps(ys, zs)));
}

// The lowest and highest finite x[i], i < n, and whether all are finite.
LANES void rangeOf16(const float* x, size_t n, float& lo, float& hi, bool& allFinite) {
    __mmask16 nonFinite = 0;
    __m512 low = _mm512_set1_ps(INFINITY), high = _mm512_set1_ps(-INFINITY);
    for (size_t i = 0; i < n; i += 16) {
        const Active active = activeLanes(n - i);
        const Floats q = loadActive(active, x + i);
        const Active finite = finiteAmong(active, q);
        low = _mm512_mask_min_ps(low, finite, low, q);
        high = _mm512_mask_max_ps(high, finite, high, q);
        nonFinite |= __mmask16(active & ~finite);
    }
    allFinite = nonFinite == 0;
    alignas(64) float lanes[2][16]; // (GCC's reductions read an undefined register)
    _mm512_store_ps(lanes[0], low);
    _mm512_store_ps(lanes[1], high);
    lo = *std::min_element(lanes[0], lanes[0] + 16);
    hi = *std::max_element(lanes[1], lanes[1] + 16);
}

// The four corners' parts of the row's lattice: parts[c * stride + j] = the part of corner c's
// hash at lattice x j for the corner's y and z fractions.
LANES void makeParts16(const float* cornerY, const float* cornerZ, const int32_t* hashes, size_t entries,
                       size_t stride, float* parts) {
    for (size_t c = 0; c < kCorners; ++c) {
        alignas(64) float partOfHash[16];
        partsOfHashes16(cornerY[c], cornerZ[c], partOfHash);
        const __m512 table = _mm512_load_ps(partOfHash);
        for (size_t j = 0; j < entries; j += 16) {
            const Active active = activeLanes(entries - j);
            const __m512i hash = _mm512_maskz_loadu_epi32(active, hashes + c * stride + j);
            _mm512_mask_storeu_ps(parts + c * stride + j, active, _mm512_maskz_permutexvar_ps(0xFFFF, hash, table));
        }
    }
}

// The permutation pairs at i & 255.
LANES inline __m512i pairAt16(const int* pairs, __m512i i) {
    return _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), 0xFFFF, _mm512_and_si512(i, _mm512_set1_epi32(255)), pairs, 4);
}

// RowHashes' tables for lattice x = X0 + j, j < entries (perlin3's hashes, as makeRowHashes
// makes them), sixteen entries at a time from the permutation's pairs.
LANES void makeRowHashes16(int X0, int Y, int Z, size_t entries, size_t stride, int32_t* hashes, float* lowCoefficients,
                           float* highCoefficients) {
    const int* perm = perlinPermutation().data();
    const int* pairs = noise::permutationPairs().data();
    const __m512i byte = _mm512_set1_epi32(255), nibble = _mm512_set1_epi32(15);
    const __m512 low = _mm512_loadu_ps(kXCoefficients[0].data()), high = _mm512_loadu_ps(kXCoefficients[1].data());
    for (size_t j = 0; j < entries; j += 16) {
        const Active active = activeLanes(entries - j);
        const __m512i X = _mm512_and_si512(_mm512_add_epi32(_mm512_set1_epi32(X0 + int(j)),
                                                            _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15)),
                                           byte);
        const __m512i A = _mm512_add_epi32(_mm512_mask_i32gather_epi32(_mm512_setzero_si512(), 0xFFFF, X, perm, 4),
                                           _mm512_set1_epi32(Y));
        const __m512i pairA = pairAt16(pairs, A); // perm(A), perm(A + 1)
        const __m512i AA = _mm512_add_epi32(_mm512_and_si512(pairA, byte), _mm512_set1_epi32(Z));
        const __m512i AB = _mm512_add_epi32(_mm512_maskz_srli_epi32(0xFFFF, pairA, 8), _mm512_set1_epi32(Z));
        const __m512i pairAA = pairAt16(pairs, AA), pairAB = pairAt16(pairs, AB);
        // (the unmasked shifts read an undefined register)
        const __m512i corners[kCorners] = {_mm512_and_si512(pairAA, nibble), _mm512_and_si512(pairAB, nibble),
                                           _mm512_and_si512(_mm512_maskz_srli_epi32(0xFFFF, pairAA, 8), nibble),
                                           _mm512_and_si512(_mm512_maskz_srli_epi32(0xFFFF, pairAB, 8), nibble)};
        for (size_t c = 0; c < kCorners; ++c) {
            _mm512_mask_storeu_epi32(hashes + c * stride + j, active, corners[c]);
            _mm512_mask_storeu_ps(lowCoefficients + c * stride + j, active, _mm512_maskz_permutexvar_ps(0xFFFF, corners[c], low));
            _mm512_mask_storeu_ps(highCoefficients + c * stride + j, active,
                                  _mm512_maskz_permutexvar_ps(0xFFFF, corners[c], high));
        }
    }
}

} // namespace rowLanes16

#undef LANES

// Eight lanes (AVX2): a mask of lanes is a register of all-ones lanes.
namespace rowLanes8 {
#define LANES __attribute__((target("avx2")))

using namespace noise::simd8; // Floats, add, sub, mul, splat, floorOf
using Ints = __m256i;
using Active = __m256;
constexpr size_t kLanes = 8;

LANES inline Floats magnitude(Floats v) { return _mm256_andnot_ps(splat(-0.0f), v); }
LANES inline Active activeLanes(size_t count) {
    const int32_t lanes = int32_t(std::min<size_t>(count, 8));
    return _mm256_castsi256_ps(_mm256_cmpgt_epi32(_mm256_set1_epi32(lanes), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7)));
}
LANES inline Floats loadActive(Active active, const float* from) {
    return _mm256_maskload_ps(from, _mm256_castps_si256(active));
}
LANES inline void storeActive(float* to, Active active, Floats v) { _mm256_maskstore_ps(to, _mm256_castps_si256(active), v); }
LANES inline Active finiteAmong(Active active, Floats v) {
    return _mm256_and_ps(active, _mm256_cmp_ps(magnitude(v), splat(INFINITY), _CMP_LT_OQ));
}
LANES inline Floats select(Active where, Floats otherwise, Floats v) { return _mm256_blendv_ps(otherwise, v, where); }
LANES inline Ints truncate(Floats v) { return _mm256_cvttps_epi32(v); }
LANES inline Ints minus(Ints a, int32_t b) { return _mm256_sub_epi32(a, _mm256_set1_epi32(b)); }
LANES inline bool anyOutside(Active active, Ints idx) {
    return !_mm256_testz_si256(_mm256_and_si256(idx, _mm256_castps_si256(active)), _mm256_set1_epi32(~7));
}
LANES inline bool allZero(Ints idx) { return _mm256_testz_si256(idx, idx) != 0; }
LANES inline Floats permuted(const float* table, Ints idx) { return _mm256_permutevar8x32_ps(_mm256_loadu_ps(table), idx); }

#include "NoiseRowLanes.inc"

#undef LANES
} // namespace rowLanes8
#endif

} // namespace

VOXC_SIMD_KERNEL void FractalRow::perlinOctave(FractalRow& row, int32_t octave, const float* x, float frequency,
                                               PointRange range, float qy, float qz, uint32_t seed, OctaveTerm term,
                                               size_t n, float* out) {
    if (!std::isfinite(qy) || !std::isfinite(qz) || range.empty()) {
        for (size_t i = 0; i < n; ++i) addTerm(noise::kNaN, term, out[i]);
        return;
    }
    // The lowest and highest lattice x: from the row's lowest and highest x where scaling keeps
    // their order (floor and a rounded product by a positive frequency are monotonic), else by
    // scaling every point first.
    const float* points = x;
    float scale = frequency, lo = std::floor(range.lo * frequency), hi = std::floor(range.hi * frequency);
    bool allFinite = range.allFinite;
    if (!(frequency > 0.0f && std::isfinite(lo) && std::isfinite(hi))) {
        row.scaled_.resize(n);
        scaleRow(x, frequency, n, row.scaled_.data(), lo, hi, allFinite);
        points = row.scaled_.data(), scale = 1.0f; // (x * 1 is x, bit for bit)
        if (!(lo <= hi)) { // no finite point
            for (size_t i = 0; i < n; ++i) addTerm(noise::kNaN, term, out[i]);
            return;
        }
    }
    if (!(hi - lo <= kMaxCellsPerPoint * float(n)) || std::max(-lo, hi) >= kExactFloors) {
        for (size_t i = 0; i < n; ++i) addTerm(noise::perlin3({points[i] * scale, qy, qz}, seed), term, out[i]);
        return;
    }

    const float fy = std::floor(qy), fz = std::floor(qz);
    const int Y = (noise::latticeIndex(fy) + noise::seedOffset(seed, 1)) & 255;
    const int Z = (noise::latticeIndex(fz) + noise::seedOffset(seed, 2)) & 255;
    const int X0 = (noise::latticeIndex(lo) + noise::seedOffset(seed, 0)) & 255;
    const size_t entries = size_t(hi - lo) + 2; // lattice x = lo .. hi + 1
    const size_t stride = entries + kTablePadding;
    if (row.rowHashes_.size() <= size_t(octave) * 256) row.rowHashes_.resize(size_t(octave + 1) * 256);
    RowHashes& h = row.rowHashes_[size_t(octave) * 256 + size_t(Y)];
    if (!(h.made && h.seed == seed && h.X0 == X0 && h.Z == Z && h.entries == entries)) {
        h.made = true, h.seed = seed, h.X0 = X0, h.Z = Z, h.entries = entries;
        // (entries past `entries` are padding a load may read: any initialised values)
        h.hashes.resize(std::max(h.hashes.size(), kCorners * stride));
        h.lowCoefficients.resize(h.hashes.size());
        h.highCoefficients.resize(h.hashes.size());
#ifdef VOXC_NOISE_ROW_AVX512
        if (hostSimd() == Simd::Avx512)
            rowLanes16::makeRowHashes16(X0, Y, Z, entries, stride, h.hashes.data(), h.lowCoefficients.data(), h.highCoefficients.data());
        else
#endif
            makeRowHashes(X0, Y, Z, entries, stride, h.hashes.data(), h.lowCoefficients.data(), h.highCoefficients.data());
    }
    // The parts for this row's y and z fractions: sixteen per corner, one per hash.
    const float y = qy - fy, z = qz - fz, y1 = y - 1.0f, z1 = z - 1.0f;
    const float cornerY[kCorners] = {y, y1, y, y1}, cornerZ[kCorners] = {z, z, z1, z1};
    if (row.parts_.size() < kCorners * stride) row.parts_.resize(kCorners * stride, 0.0f);
    const RowLattice lattice{row.parts_.data(), h.lowCoefficients.data(), h.highCoefficients.data(), stride,
                             lo,            noise::fade(y),           noise::fade(z)};
#ifdef VOXC_NOISE_ROW_AVX512
    if (hostSimd() == Simd::Avx512) {
        rowLanes16::makeParts16(cornerY, cornerZ, h.hashes.data(), entries, stride, row.parts_.data());
        if (allFinite) return rowLanes16::perlinPoints<true>(lattice, points, scale, term, n, out);
        return rowLanes16::perlinPoints<false>(lattice, points, scale, term, n, out);
    }
#endif
    for (size_t c = 0; c < kCorners; ++c)
        for (size_t j = 0; j < entries; ++j)
            row.parts_[c * stride + j] = gradientPart(h.hashes[c * stride + j], cornerY[c], cornerZ[c]);
#ifdef VOXC_NOISE_ROW_AVX512
    if (hostSimd() == Simd::Avx2) {
        if (allFinite) return rowLanes8::perlinPoints<true>(lattice, points, scale, term, n, out);
        return rowLanes8::perlinPoints<false>(lattice, points, scale, term, n, out);
    }
#endif
    for (size_t i = 0; i < n; ++i) addTerm(perlinAtPoint(lattice, points[i] * scale), term, out[i]);
}

VOXC_SIMD_KERNEL void FractalRow::octaveSum(FractalRow& row, FractalFold fold, const float* x, float y, float z,
                                            int32_t octaves, float lacunarity, float gain, uint32_t seed, size_t n,
                                            float* out) {
    PointRange range;
#ifdef VOXC_NOISE_ROW_AVX512
    if (hostSimd() == Simd::Avx512) rowLanes16::rangeOf16(x, n, range.lo, range.hi, range.allFinite);
    else
#endif
        for (size_t i = 0; i < n; ++i) {
            if (std::isfinite(x[i])) range.lo = std::min(range.lo, x[i]), range.hi = std::max(range.hi, x[i]);
            else range.allFinite = false;
        }
    if (fold == FractalFold::Ridged) row.weight_.assign(n, 1.0f), row.noise_.resize(n);
    // noise::fbm's octave loop (Fractal.cpp), each point's terms summed in the same order.
    float amplitude = 1.0f, frequency = 1.0f;
    const int32_t count = std::min(std::max(octaves, 1), noise::kMaxOctaves);
    for (int32_t k = 0; k < count; ++k) {
        const float qy = y * frequency, qz = z * frequency;
        const uint32_t octaveSeed = noise::substream(seed, uint32_t(k));
        if (fold != FractalFold::Ridged) {
            perlinOctave(row, k, x, frequency, range, qy, qz, octaveSeed, {fold, amplitude, k == 0, false}, n, out);
        } else {
            perlinOctave(row, k, x, frequency, range, qy, qz, octaveSeed, {fold, amplitude, true, true}, n, row.noise_.data());
            for (size_t i = 0; i < n; ++i) {
                float s = 1.0f - std::fabs(row.noise_[i]);
                s = s * s;
                s = s * row.weight_[i];
                row.weight_[i] = std::min(std::max(s * 2.0f, 0.0f), 1.0f);
                const float weighted = amplitude * s;
                out[i] = k == 0 ? weighted : out[i] + weighted;
            }
        }
        amplitude = amplitude * gain;
        frequency = frequency * lacunarity;
    }
}

void FractalRow::evaluate(FractalFold fold, const float* x, float y, float z, int32_t octaves, float lacunarity,
                          float gain, uint32_t seed, size_t n, float* out) {
    // The setup of every octave's table (floors, fades, lattice indices) compiled for the host's
    // widest SIMD too: the baseline has no scalar floor instruction.
    atHostSimd<&FractalRow::octaveSum>(*this, fold, x, y, z, octaves, lacunarity, gain, seed, n, out);
}

} // namespace voxc
