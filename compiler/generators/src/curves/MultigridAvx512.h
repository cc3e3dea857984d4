#pragma once
// The host multigrid's AVX-512 slice kernels (Multigrid.cpp): a half sweep of one colour and the
// max residual with f = 0, a slice per call, each cell the same expression in the same order as
// the row kernels, so the same bits. GCC on x86-64 only (VOXC_COLOUR_KERNEL); they run where
// hasColourKernel() says so (the CPU has AVX-512 F, BW, DQ and VL and VOXC_SIMD allows them).
#include <cstdint>

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define VOXC_COLOUR_KERNEL 1

namespace voxc::curves {

// One slice of a level's component, its neighbours and its mask.
struct SliceRows {
    float* u;                 // the slice's first row
    const float *below, *above; // the slices z - 1 and z + 1 (null where outside the box)
    const float* rhs;         // the slice's right-hand side (null: 0)
    const uint8_t* fixed;     // the slice's mask
    const float* zeros;       // a row of n zeros
    int32_t n, rows;
    float wx, wy, wz;
    int32_t firstParity; // (y + z + colour) & 1 at y = 0
};

bool hasColourKernel();

// One colour of a whole slice in AVX-512 registers, only that colour's cells computed (relaxRow
// and storeRelaxed compute every cell and keep half), the end cells included. Each block of 32
// columns from xs (the row's first cell of the colour) holds 16 of the colour's cells, x = xs +
// 2k: their own values and their y/z neighbours (the other colour, at the same x) are the even
// lanes of two loads, their +x neighbours the odd lanes, their -x neighbours the odd lanes one
// lane later (the block before's last in lane 0). A missing neighbour adds an exact +0 (masked
// loads past the row's end, the zeros row past the box; as in relaxRow, a sum from +0 is never
// -0, so s + (+0) = s), and an end cell divides by its own sum of weights, in neighbour order as
// relaxColourRow's per-cell path sums them: so each lane computes relaxRow's (relaxRowFinest's)
// or the end cell's expression, term by term in neighbour order (+, *, / per lane round as the
// scalar ones; the build has -ffp-contract=off), and a masked store writes the colour's free cells
// only, so it also serves the middle slices (exactWrites). The blocks inside a row that hold
// neither end cell load without masks and divide by the interior weights: the same values.
// `finest`: every weight 1 and no right-hand side. Rows of at least 2 cells.
void relaxColourSliceAvx512(const SliceRows& s, bool finest);

// max(worst, max |r|) over the free cells of a slice, r = 0 - sum_j w_j (u_j - u_i) (f = 0, as
// residualRow with a null right-hand side, then maxAbs): 16 cells per AVX-512 register, each the
// same expression in neighbour order; a missing neighbour, in x as in y and z, is the cell itself
// (u_i - u_i = +0 changes no sum from +0, as residualRow's absent rows), and fixed cells (r = 0)
// are left out of the max, which does not depend on the order (max(w, NaN) keeps w, as std::max).
// The blocks whose x neighbours all lie in the row load without masks (the same values).
// `finest`: every weight 1. Rows of at least 2 cells; s.rhs is not read.
float maxResidualSliceAvx512(const SliceRows& s, bool finest, float worst);

} // namespace voxc::curves
#endif
