#include "voxc/generators/curves/Multigrid.h"

#include "MultigridAvx512.h"
#include "Parallel.h"
#include "voxc/core/Simd.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <span>

namespace voxc::curves {
namespace {

// V(3,3), not the spec's V(2,2) (kPreSmooth, kPostSmooth in Multigrid.h), with an over-relaxed
// smoother (kOverRelaxation = 1.5). A coarse cell with any constrained child is Dirichlet, so the
// coarse correction is weak in a band around the constraints as wide as the coarse cells; the
// error left there is smooth, which plain Gauss-Seidel (omega = 1) removes slowly (convergence
// factor per V-cycle 0.25-0.38 on the cliff scene) and over-relaxation quickly (0.08-0.17; the
// full-multigrid start's residual also drops 2.6x). V(2,2) with it needs one cycle more for the
// same work (docs/curves.md).

// A level's cells are `1 << scale[a]` finest cells wide along axis a; its stencil weights axis a
// by 1 / width^2 (exact powers of 1/4), so every level discretises the same Laplacian in finest
// units and the coarse right-hand side is the plain mean of the fine residual.
struct Level {
    Box box;
    glm::vec3 weight{1.0f};
    // The Dirichlet mask: the caller's at the finest level (not copied), coarserMasks' below.
    std::span<const uint8_t> fixed;
    std::vector<std::vector<float>> u, f; // per component: unknowns (or corrections) and right-hand side
    // Per component: the coarser level's correction interpolated along x (Prolongation::prepare),
    // kept between V-cycles so its pages are touched once per solve.
    std::vector<std::vector<float>> alongX;
};

// Visits the in-box face neighbours in the order -x, +x, -y, +y, -z, +z as (index, axis).
template <typename Visit>
void forNeighbours(const Box& b, int32_t x, int32_t y, int32_t z, Visit&& visit) {
    const size_t i = b.index(x, y, z), row = size_t(b.size.x), slice = row * size_t(b.size.y);
    if (x > 0) visit(i - 1, 0);
    if (x + 1 < b.size.x) visit(i + 1, 0);
    if (y > 0) visit(i - row, 1);
    if (y + 1 < b.size.y) visit(i + row, 1);
    if (z > 0) visit(i - slice, 2);
    if (z + 1 < b.size.z) visit(i + slice, 2);
}

// The row loops below compute, for the cells 1..n-2 of a row (both x neighbours inside), the
// same float expression as the per-cell loop, term by term in neighbour order, into a scratch row
// the compiler vectorises; the two end cells take the per-cell path. A neighbour row outside the
// box contributes an exact +0 instead of being skipped: a sum that starts at +0 is never -0 (x + y
// is -0 only when both are), and s + (+0) = s for every s that is not -0, so the sums, and with
// them every bit, equal those of the loop that skips it.

// Passes over a level of at least this many cells run on two threads (smooth: half the slices
// each; the order-free passes through forTwoSlabs). A smaller level's pass takes well under a
// millisecond, less than starting a thread costs on a loaded machine, where the new thread
// waits for a core (with 32,768 cells and 16 slices, the levels of 64x32x64 and 32x16x32 cells
// took 90 ms of the normals' solve at 256x128x256 at a load of 6, against 51 ms now).
constexpr uint64_t kMinCellsForThreads = 1u << 18;
// forTwoSlabs' minimum slice count for a pass over `cells` cells.
int32_t minSlicesForThreads(uint64_t cells) { return cells >= kMinCellsForThreads ? 2 : INT32_MAX; }

// The row kernels run compiled for AVX-512 (x86-64-v4) or AVX2 where the CPU has them and
// VOXC_SIMD allows (atHostSimd, voxc/core/Simd.h): elementwise IEEE +, x, / give the same bits at
// every width, and the build has -ffp-contract=off (no FMA changes a rounding). The AVX-512 form
// took 0.77-0.96x the row kernels' CPU samples of the AVX2 one at 256x128x256 (load 8.7-9.3).
// It is x86-64-v4's (AVX-512 F, BW, DQ, VL, CD), not AVX512F's alone: byte masks and 32-bit
// lanes convert and compare in mask registers, which cut the multigrid's samples by about 7%
// (storeRelaxed about 15%).

// A row's own values and its four y/z neighbour rows (`absent` where outside the box).
struct RowNeighbours {
    const float *ym, *yp, *zm, *zp;
};
RowNeighbours rowNeighbours(const Box& b, const float* u, int32_t y, int32_t z, const float* absent) {
    const size_t row = size_t(b.size.x), slice = row * size_t(b.size.y), i = b.index(0, y, z);
    return {y > 0 ? u + i - row : absent, y + 1 < b.size.y ? u + i + row : absent, z > 0 ? u + i - slice : absent,
            z + 1 < b.size.z ? u + i + slice : absent};
}

// The over-relaxed update of a cell whose Gauss-Seidel value is `relaxed`.
inline float overRelaxed(float u, float relaxed, float omega) { return u + omega * (relaxed - u); }

// out[x] = overRelaxed(centre[x], (sum_j w_j u_j - rhs[x]) / weights) for x in [1, n - 1), the
// sum from 0 in neighbour order. Plain arguments and restrict pointers let the compiler vectorise
// it (elementwise only: no operation is reordered). Every cell is computed, so the store is a
// plain select (a select around the arithmetic would not be if-converted: it may trap).
VOXC_SIMD_KERNEL
void relaxRow(const float* __restrict centre, const float* __restrict ym, const float* __restrict yp,
              const float* __restrict zm, const float* __restrict zp, const float* __restrict rhs, float wx, float wy,
              float wz, float weights, float omega, int32_t n, float* __restrict out) {
    for (int32_t x = 1; x + 1 < n; ++x) {
        float sum = 0.0f;
        sum += wx * centre[x - 1];
        sum += wx * centre[x + 1];
        sum += wy * ym[x];
        sum += wy * yp[x];
        sum += wz * zm[x];
        sum += wz * zp[x];
        out[x] = overRelaxed(centre[x], (sum - rhs[x]) / weights, omega);
    }
}

// relaxRow on the finest level, where every weight is 1 and the right-hand side 0: 1 * v = v
// and s - (+0) = s for every float (-0 included), so the same bits with seven operations fewer
// per cell of the fourteen left after the loads (the row kernels are bound by their arithmetic:
// in L1, relaxRow takes the same time with its division replaced by a multiplication).
VOXC_SIMD_KERNEL
void relaxRowFinest(const float* __restrict centre, const float* __restrict ym, const float* __restrict yp,
                    const float* __restrict zm, const float* __restrict zp, float weights, float omega, int32_t n,
                    float* __restrict out) {
    for (int32_t x = 1; x + 1 < n; ++x) {
        float sum = 0.0f;
        sum += centre[x - 1];
        sum += centre[x + 1];
        sum += ym[x];
        sum += yp[x];
        sum += zm[x];
        sum += zp[x];
        out[x] = overRelaxed(centre[x], sum / weights, omega);
    }
}

// u[x] = relaxed[x] for x in [1, n - 1) where the cell is free and (x + parity) is even (the
// half sweep's colour in a row of that parity); a branch-free select, so it vectorises, with
// relaxed read at every cell (read on one side of the select only, it took masked loads). (Masks
// of the cells to keep, per level and parity, cost as much to read and 2 bytes per cell of fresh
// memory.)
VOXC_SIMD_KERNEL
void storeRelaxed(const float* __restrict relaxed, const uint8_t* __restrict fixed, int32_t parity, int32_t n,
                  float* __restrict u) {
    for (int32_t x = 1; x + 1 < n; ++x) {
        const float next = relaxed[x];
        u[x] = (fixed[x] | ((x + parity) & 1)) ? u[x] : next;
    }
}

// Red-black over-relaxed Gauss-Seidel half sweep of colour `colour` on row (y, z) of component
// c: u_i += omega * (g_i - u_i), g_i = (sum_j w_j u_j - f_i) / sum_j w_j, both sums from 0 in
// neighbour order (on the finest level w = 1: the plain neighbour sum over the count). A colour's cells read only the other
// colour, so rows and slices may run in any order. `relaxed` is a scratch row of n floats.
// `exactWrites`: store only the colour's cells (a row another thread reads during the sweep);
// otherwise the select rewrites the other colour's cells with their own values.
void relaxColourRow(Level& level, size_t c, int32_t colour, bool zeroRhs, int32_t y, int32_t z, bool exactWrites,
                    const float* zeros, float* relaxed) {
    const Box& b = level.box;
    const int32_t n = b.size.x;
    const float wx = level.weight.x, wy = level.weight.y, wz = level.weight.z;
    const float omega = kOverRelaxation;
    float* u = level.u[c].data();
    const size_t i0 = b.index(0, y, z);
    const float* rhs = zeroRhs ? zeros : level.f[c].data() + i0;
    const RowNeighbours r = rowNeighbours(b, u, y, z, zeros);
    // Weights of the present neighbours, in neighbour order.
    float weights = 0.0f;
    weights += wx, weights += wx;
    if (y > 0) weights += wy;
    if (y + 1 < b.size.y) weights += wy;
    if (z > 0) weights += wz;
    if (z + 1 < b.size.z) weights += wz;
    const int32_t parity = (y + z + colour) & 1;
    const uint8_t* fixed = level.fixed.data() + i0;
    const bool finest = zeroRhs && wx == 1.0f && wy == 1.0f && wz == 1.0f;
    if (finest)
        atHostSimd<relaxRowFinest>(u + i0, r.ym, r.yp, r.zm, r.zp, weights, omega, n, relaxed);
    else
        atHostSimd<relaxRow>(u + i0, r.ym, r.yp, r.zm, r.zp, rhs, wx, wy, wz, weights, omega, n, relaxed);
    if (exactWrites) {
        for (int32_t x = 2 - parity; x + 1 < n; x += 2)
            if (!fixed[x]) u[i0 + size_t(x)] = relaxed[x];
    } else {
        atHostSimd<storeRelaxed>(relaxed, fixed, parity, n, u + i0);
    }
    // The end cells (a missing x neighbour): the per-cell sums over the neighbours present, in
    // neighbour order (forNeighbours' visits written out with the row's weights).
    const size_t row = size_t(n), slice = row * size_t(b.size.y);
    auto endCell = [&](int32_t x) {
        if (((x + parity) & 1) || fixed[x]) return;
        const size_t i = i0 + size_t(x);
        float sum = 0.0f, total = 0.0f;
        if (x > 0) sum += wx * u[i - 1], total += wx;
        if (x + 1 < n) sum += wx * u[i + 1], total += wx;
        if (y > 0) sum += wy * u[i - row], total += wy;
        if (y + 1 < b.size.y) sum += wy * u[i + row], total += wy;
        if (z > 0) sum += wz * u[i - slice], total += wz;
        if (z + 1 < b.size.z) sum += wz * u[i + slice], total += wz;
        if (total > 0.0f) u[i] = overRelaxed(u[i], (sum - rhs[x]) / total, omega);
    };
    endCell(0);
    if (n > 1) endCell(n - 1);
}


#ifdef VOXC_COLOUR_KERNEL
// Slice z of `u` (a component of `level`, or values over its box) and its neighbours, for the
// AVX-512 slice kernels.
SliceRows sliceRows(const Level& level, float* u, int32_t z, const float* rhs, const float* zeros, int32_t firstParity) {
    const Box& b = level.box;
    const size_t slice = size_t(b.size.x) * size_t(b.size.y), i0 = slice * size_t(z);
    return {u + i0,
            z > 0 ? u + i0 - slice : nullptr,
            z + 1 < b.size.z ? u + i0 + slice : nullptr,
            rhs ? rhs + i0 : nullptr,
            level.fixed.data() + i0,
            zeros,
            b.size.x,
            b.size.y,
            level.weight.x,
            level.weight.y,
            level.weight.z,
            firstParity};
}
#endif

// One colour's half sweep of slice z of component c: relaxColourRow on every row, or where the
// CPU has AVX-512 and rows have at least 2 cells, relaxColourSliceAvx512 (the same bits).
void relaxColourSlice(Level& level, size_t c, int32_t colour, bool zeroRhs, int32_t z, bool exactWrites,
                      const float* zeros, float* relaxed) {
    const Box& b = level.box;
#ifdef VOXC_COLOUR_KERNEL
    if (b.size.x >= 2 && hasColourKernel()) {
        relaxColourSliceAvx512(sliceRows(level, level.u[c].data(), z, zeroRhs ? nullptr : level.f[c].data(), zeros, (z + colour) & 1),
                               zeroRhs && level.weight == glm::vec3(1.0f));
        return;
    }
#endif
    for (int32_t y = 0; y < b.size.y; ++y) relaxColourRow(level, c, colour, zeroRhs, y, z, exactWrites, zeros, relaxed);
}

// r = f - sum_j w_j (u_j - u_i) on free cells (the caller skips fixed ones).
float residualAt(const Level& level, const std::vector<float>& u, float f, int32_t x, int32_t y, int32_t z) {
    const size_t i = level.box.index(x, y, z);
    float lap = 0.0f;
    forNeighbours(level.box, x, y, z, [&](size_t j, int32_t axis) { lap += level.weight[axis] * (u[j] - u[i]); });
    return f - lap;
}

// out[x] = rhs[x] - sum_j w_j (u_j - u_i) for x in [1, n - 1) (rhs null: 0), the sum from 0 in
// neighbour order; vectorisable like relaxRow.
VOXC_SIMD_KERNEL
void laplaceResidualRow(const float* __restrict u, const float* __restrict ym, const float* __restrict yp,
                        const float* __restrict zm, const float* __restrict zp, const float* __restrict rhs, float wx,
                        float wy, float wz, int32_t n, float* __restrict out) {
    for (int32_t x = 1; x + 1 < n; ++x) {
        const float centre = u[x];
        float lap = 0.0f;
        lap += wx * (u[x - 1] - centre);
        lap += wx * (u[x + 1] - centre);
        lap += wy * (ym[x] - centre);
        lap += wy * (yp[x] - centre);
        lap += wz * (zm[x] - centre);
        lap += wz * (zp[x] - centre);
        out[x] = (rhs ? rhs[x] : 0.0f) - lap;
    }
}

// laplaceResidualRow with every weight 1 and no right-hand side (the finest level): 1 * v = v,
// so the same bits with six multiplications fewer per cell.
VOXC_SIMD_KERNEL
void laplaceResidualRowFinest(const float* __restrict u, const float* __restrict ym, const float* __restrict yp,
                              const float* __restrict zm, const float* __restrict zp, int32_t n, float* __restrict out) {
    for (int32_t x = 1; x + 1 < n; ++x) {
        const float centre = u[x];
        float lap = 0.0f;
        lap += u[x - 1] - centre;
        lap += u[x + 1] - centre;
        lap += ym[x] - centre;
        lap += yp[x] - centre;
        lap += zm[x] - centre;
        lap += zp[x] - centre;
        out[x] = 0.0f - lap;
    }
}

// out[x] = 0 where fixed[x]; a select, so it vectorises.
VOXC_SIMD_KERNEL
void zeroFixed(const uint8_t* __restrict fixed, int32_t n, float* __restrict out) {
    for (int32_t x = 0; x < n; ++x) out[x] = fixed[x] ? 0.0f : out[x];
}

// The residuals of row (y, z) into out[0..n): f - sum_j w_j (u_j - u_i) at free cells, 0 at fixed
// ones; f is 0 where `rhs` is null. An absent neighbour row is the row itself (u_j - u_i = +0).
void residualRow(const Level& level, const std::vector<float>& values, const float* rhs, int32_t y, int32_t z,
                 float* out) {
    const Box& b = level.box;
    const int32_t n = b.size.x;
    const size_t i0 = b.index(0, y, z);
    const float* u = values.data() + i0;
    const RowNeighbours r = rowNeighbours(b, values.data(), y, z, u);
    if (!rhs && level.weight == glm::vec3(1.0f))
        atHostSimd<laplaceResidualRowFinest>(u, r.ym, r.yp, r.zm, r.zp, n, out);
    else
        atHostSimd<laplaceResidualRow>(u, r.ym, r.yp, r.zm, r.zp, rhs ? rhs + i0 : nullptr, level.weight.x,
                                       level.weight.y, level.weight.z, n, out);
    out[0] = residualAt(level, values, rhs ? rhs[i0] : 0.0f, 0, y, z);
    if (n > 1) out[n - 1] = residualAt(level, values, rhs ? rhs[i0 + size_t(n - 1)] : 0.0f, n - 1, y, z);
    atHostSimd<zeroFixed>(level.fixed.data() + i0, n, out);
}

// Which axes the next level halves (ceil): every axis of >= 2 cells while the longest has >= 8;
// none: this is the coarsest level. Short axes go down to one cell with the others, so cell
// widths stay equal across axes where there are neighbours (a pointwise smoother fails on
// stretched cells).
glm::ivec3 halvedAxes(const Box& b) {
    if (std::max({b.size.x, b.size.y, b.size.z}) < 8) return glm::ivec3(0);
    return glm::ivec3(b.size.x >= 2, b.size.y >= 2, b.size.z >= 2);
}

// The coarse rows interpolated along x at every fine column: out[x] = near * row[x0[x]] + far *
// row[x1[x]] (the trilinear prolongation's first step), gathers through the parent columns.
VOXC_SIMD_KERNEL
void interpolateAlongX(const float* __restrict row, const int32_t* __restrict x0, const int32_t* __restrict x1,
                       float near, float far, int32_t n, float* __restrict out) {
    for (int32_t x = 0; x < n; ++x) out[x] = near * row[x0[x]] + far * row[x1[x]];
}

// The four rows of coarse values interpolated along x that a fine row combines, [k][j]: those of
// coarse row (ys[j], zs[k]).
struct AlongXRows {
    const float *r00, *r01, *r10, *r11;
};

// A fine row of the prolongation from rows interpolated along x: per cell y, then z, in the
// order of the per-cell expression, stored (or added) where the cell is free. Each block of cells
// is first computed at every cell into a local row (added to out where `add`), then stored with a
// branch-free select that keeps the fixed cells: a select around the arithmetic, or a load only
// one side of it makes, is not if-converted (it may trap) and leaves the loop scalar.
VOXC_SIMD_KERNEL
void prolongRow(AlongXRows c, float n1, float f1, float n2, float f2, const uint8_t* __restrict fixed, bool add,
                int32_t n, float* __restrict out) {
    const float* __restrict r00 = c.r00;
    const float* __restrict r01 = c.r01;
    const float* __restrict r10 = c.r10;
    const float* __restrict r11 = c.r11;
    constexpr int32_t kBlock = 64;
    float values[kBlock];
    for (int32_t x0 = 0; x0 < n; x0 += kBlock) {
        const int32_t m = std::min(kBlock, n - x0);
        if (add) {
            for (int32_t k = 0; k < m; ++k) {
                const int32_t x = x0 + k;
                values[k] = out[x] + (n2 * (n1 * r00[x] + f1 * r01[x]) + f2 * (n1 * r10[x] + f1 * r11[x]));
            }
        } else {
            for (int32_t k = 0; k < m; ++k) {
                const int32_t x = x0 + k;
                values[k] = n2 * (n1 * r00[x] + f1 * r01[x]) + f2 * (n1 * r10[x] + f1 * r11[x]);
            }
        }
        for (int32_t k = 0; k < m; ++k) out[x0 + k] = fixed[x0 + k] ? out[x0 + k] : values[k];
    }
}

// max(worst, max_x |values[x]|): eight running maxima, merged at the end (a max does not depend
// on the order, so the result is the plain loop's; the values are finite), so it vectorises.
VOXC_SIMD_KERNEL
float maxAbs(const float* __restrict values, int32_t n, float worst) {
    float lanes[8] = {worst, worst, worst, worst, worst, worst, worst, worst};
    int32_t x = 0;
    for (; x + 8 <= n; x += 8)
        for (int32_t k = 0; k < 8; ++k) lanes[k] = std::max(lanes[k], std::abs(values[x + k]));
    for (; x < n; ++x) lanes[0] = std::max(lanes[0], std::abs(values[x]));
    for (int32_t k = 1; k < 8; ++k) lanes[0] = std::max(lanes[0], lanes[k]);
    return lanes[0];
}

// max(worst, the max |r| with f = 0 over the free cells of slice z of `u`): residualRow and
// maxAbs per row, or where the CPU has AVX-512 and rows have at least 2 cells,
// maxResidualSliceAvx512 (the same value). `residual` is a scratch row of n floats.
float maxResidualOfSlice(const Level& level, const std::vector<float>& u, int32_t z, float* residual, float worst) {
    const Box& b = level.box;
#ifdef VOXC_COLOUR_KERNEL
    if (b.size.x >= 2 && hasColourKernel())
        return maxResidualSliceAvx512(sliceRows(level, const_cast<float*>(u.data()) /* read only */, z, nullptr, nullptr, 0),
                                      level.weight == glm::vec3(1.0f), worst);
#endif
    for (int32_t y = 0; y < b.size.y; ++y) {
        residualRow(level, u, nullptr, y, z, residual);
        worst = atHostSimd<maxAbs>(residual, b.size.x, worst);
    }
    return worst;
}

// Trilinear cell-centred interpolation of coarse values at every free fine cell, along x, then
// y, then z: on a halved axis weights 3/4 (own parent) and 1/4 (the next parent towards the
// child, clamped at the box), on a kept axis 1 and 0; added to or written into u. The x step of
// every coarse row is done once (prepare: each is shared by up to 16 fine rows) into a buffer of
// coarse rows at fine x resolution; a fine row (row) then combines four of them. Both are
// pointwise, so rows may be done in any order, on any thread.
class Prolongation {
public:
    Prolongation(const Box& coarse, const Level& fine) : coarse_(coarse), fine_(fine), halved_(halvedAxes(fine.box)) {
        for (int32_t a = 0; a < 3; ++a) near_[a] = halved_[a] ? 0.75f : 1.0f, far_[a] = 1.0f - near_[a];
        // Per fine x: the own and the other parent column.
        xs0_.resize(size_t(fine.box.size.x)), xs1_.resize(size_t(fine.box.size.x));
        for (int32_t x = 0; x < fine.box.size.x; ++x)
            xs0_[size_t(x)] = x >> halved_.x, xs1_[size_t(x)] = other(x, coarse.size.x, halved_.x);
    }

    // alongX = every coarse row of e interpolated along x at the fine columns (sized here).
    void prepare(const std::vector<float>& e, std::vector<float>& alongX) const {
        const int32_t n = fine_.box.size.x;
        alongX.resize(size_t(n) * size_t(coarse_.size.y) * size_t(coarse_.size.z));
        forTwoSlabs(coarse_.size.z, minSlicesForThreads(fine_.box.cellCount()), [&](int32_t z0, int32_t z1) {
            for (int32_t z = z0; z < z1; ++z)
                for (int32_t y = 0; y < coarse_.size.y; ++y)
                    atHostSimd<interpolateAlongX>(e.data() + coarse_.index(0, y, z), xs0_.data(), xs1_.data(), near_[0],
                                                  far_[0], n, alongX.data() + alongXRow(y, z));
        });
    }

    // Fine row (y, z) of u from prepare's buffer.
    void row(const std::vector<float>& alongX, std::vector<float>& u, bool add, int32_t y, int32_t z) const {
        const Box& b = fine_.box;
        const int32_t ys[2] = {y >> halved_.y, other(y, coarse_.size.y, halved_.y)};
        const int32_t zs[2] = {z >> halved_.z, other(z, coarse_.size.z, halved_.z)};
        const float* a = alongX.data();
        const AlongXRows rows{a + alongXRow(ys[0], zs[0]), a + alongXRow(ys[1], zs[0]), a + alongXRow(ys[0], zs[1]),
                              a + alongXRow(ys[1], zs[1])};
        const size_t i0 = b.index(0, y, z);
        atHostSimd<prolongRow>(rows, near_[1], far_[1], near_[2], far_[2], fine_.fixed.data() + i0, add, b.size.x,
                               u.data() + i0);
    }

private:
    static int32_t other(int32_t v, int32_t n, int32_t h) {
        return h ? std::clamp((v & 1) ? v / 2 + 1 : v / 2 - 1, 0, n - 1) : v;
    }
    size_t alongXRow(int32_t y, int32_t z) const {
        return (size_t(z) * size_t(coarse_.size.y) + size_t(y)) * size_t(fine_.box.size.x);
    }
    const Box& coarse_;
    const Level& fine_;
    glm::ivec3 halved_;
    float near_[3], far_[3];
    std::vector<int32_t> xs0_, xs1_;
};

void prolong(const Box& coarse, const std::vector<float>& e, Level& fine, std::vector<float>& u, bool add) {
    const Prolongation p(coarse, fine);
    std::vector<float>& alongX = fine.alongX.front();
    p.prepare(e, alongX);
    forTwoSlabs(fine.box.size.z, minSlicesForThreads(fine.box.cellCount()), [&](int32_t z0, int32_t z1) {
        for (int32_t z = z0; z < z1; ++z)
            for (int32_t y = 0; y < fine.box.size.y; ++y) p.row(alongX, u, add, y, z);
    });
}

// `sweeps` red-black sweeps of each component in one pass over the z slices (a wavefront), one
// component after the other (the components are independent; a single component's slices in
// flight stay nearer the core: about 0.94x the smoother's CPU samples of all components in one
// pass at 256x128x256): step t runs half sweep h (colour h & 1) on slice t - h, h = 0 .. 2 sweeps
// - 1 in order. Half sweep h of slice z reads the other colour of slices z - 1 .. z + 1 as half sweep h - 1 left
// them: slice z + 1 got it earlier in the same step, slice z in the step before, slice z - 1 two
// steps before, and half sweep h + 1 reaches none of them before h is done. So each cell takes
// the value the plain sweep-by-sweep loop gives it, bit for bit, while a sweep's slices are still
// in cache for the next. The order of the slices does not matter to that argument, so on two
// threads each runs the wavefront over its own half of the slices towards the middle (the lower
// half upwards, the upper half downwards): the two meet only at the two middle slices, where each
// thread waits before half sweep h of its middle slice until the other has done half sweep h - 1
// of its own (a counter per thread), a handful of waits per pass instead of one barrier per
// slice, which on a loaded machine mostly waited for the other thread to get a core. The middle
// slices store only the colour's cells (the other thread reads their other colour meanwhile).
// The same pass may first add a coarse correction (`correction`: slice t at step t, the sweeps
// one slice behind, so half sweep 0 of a slice finds its neighbour slices corrected; a middle
// slice's correction counts as the stage before its half sweep 0) and measure the max residual
// with f = 0 at the end (`maxResidual`: the slice two sweeps behind the last half sweep, once its
// neighbour slices are final, the middle ones after both threads are done; as maxResidualOf, and
// a max does not depend on the order).
struct Correction {
    const Prolongation& prolongation; // its prepared rows: the level's alongX
};

// A thread's share of the slices: `count` slices from `first` in steps of `direction`, the last
// of them next to the other thread's share; `own` and `other` count the stages done on this
// share's and the other share's last slice (null on one thread).
struct Slab {
    int32_t first, count, direction;
    std::atomic<int32_t>* own = nullptr;
    std::atomic<int32_t>* other = nullptr;
    int32_t slice(int32_t j) const { return first + direction * j; }
};

void smooth(Level& level, int32_t sweeps, bool zeroRhs, const Correction* correction = nullptr,
            float* maxResidual = nullptr) {
    const Box& b = level.box;
    const std::vector<float> zeros(size_t(b.size.x), 0.0f);
    const int32_t halfSweeps = 2 * std::max(sweeps, 0);
    // With a correction, step t adds it to slice t and the sweeps run one slice behind.
    const int32_t lag = correction ? 1 : 0;
    // Nothing below allocates or throws (so neither thread can leave the other waiting at the
    // middle slices; bothOf would still rethrow): the scratch rows exist before the threads start.
    std::vector<float> scratch(4 * size_t(b.size.x), 0.0f);
    const bool threaded = b.cellCount() >= kMinCellsForThreads && b.size.z >= 4;
    float worst[2] = {0.0f, 0.0f};
    auto measure = [&](const std::vector<float>& u, int32_t z, float* residual, float& w) {
        w = maxResidualOfSlice(level, u, z, residual, w);
    };
    // A component's stages on a middle slice: the correction, then the half sweeps.
    const int32_t stages = lag + halfSweeps;
    auto run = [&](const Slab& slab, float* relaxed, float* residual, float& w) {
        const int32_t last = slab.count - 1;
        const bool meets = slab.other != nullptr;
        const int32_t steps = slab.count + halfSweeps - 1 + lag + (maxResidual ? 1 : 0);
        for (size_t c = 0; c < level.u.size(); ++c) {
            // Stage k of component c is stage c * stages + k of the counters: before it, the other
            // thread's middle slice must have done the stage before (of this component, or the
            // last of the one before, whose values this stage does not read).
            const int32_t base = int32_t(c) * stages;
            auto waitFor = [&](int32_t stage) {
                for (int32_t done = slab.other->load(std::memory_order_acquire); done < base + stage;
                     done = slab.other->load(std::memory_order_acquire))
                    slab.other->wait(done, std::memory_order_acquire);
            };
            auto finished = [&](int32_t stage) {
                slab.own->store(base + stage + 1, std::memory_order_release);
                slab.own->notify_one();
            };
            for (int32_t t = 0; t < steps; ++t) {
                if (correction && t < slab.count) {
                    for (int32_t y = 0; y < b.size.y; ++y)
                        correction->prolongation.row(level.alongX[c], level.u[c], true, y, slab.slice(t));
                    if (meets && t == last) finished(0);
                }
                for (int32_t h = 0; h < halfSweeps; ++h) {
                    const int32_t j = t - lag - h;
                    if (j < 0 || j > last) continue;
                    const bool middle = meets && j == last;
                    if (middle) waitFor(lag + h);
                    relaxColourSlice(level, c, h & 1, zeroRhs, slab.slice(j), middle, zeros.data(), relaxed);
                    if (middle) finished(lag + h);
                }
                const int32_t measured = t - lag - halfSweeps;
                if (maxResidual && measured >= 0 && measured < last + (meets ? 0 : 1))
                    measure(level.u[c], slab.slice(measured), residual, w);
            }
        }
    };
    float* first = scratch.data();
    float* second = scratch.data() + 2 * size_t(b.size.x);
    if (!threaded) {
        run(Slab{0, b.size.z, 1}, first, first + b.size.x, worst[0]);
    } else {
        const int32_t mid = b.size.z / 2;
        std::atomic<int32_t> lower{0}, upper{0};
        bothOf([&] { run(Slab{0, mid, 1, &lower, &upper}, second, second + b.size.x, worst[1]); },
               [&] { run(Slab{b.size.z - 1, b.size.z - mid, -1, &upper, &lower}, first, first + b.size.x, worst[0]); });
        if (maxResidual)
            for (const std::vector<float>& u : level.u) {
                measure(u, mid - 1, first + b.size.x, worst[0]);
                measure(u, mid, first + b.size.x, worst[0]);
            }
    }
    if (maxResidual) *maxResidual = std::max(worst[0], worst[1]);
}

// The child cells of coarse index p along an axis of n fine cells: {2p, 2p + 1} (the second
// only inside) where the axis is halved, {p} where it is kept.
struct Children {
    int32_t first, count;
};
Children childrenOf(int32_t p, int32_t n, int32_t halved) {
    return halved ? Children{2 * p, std::min(2, n - 2 * p)} : Children{p, 1};
}

// Calls childRow(y, z) for the fine rows under coarse row (py, pz), z slowest, then y; returns
// their count.
template <typename ChildRow>
int32_t forChildRows(const glm::ivec3& fineSize, const glm::ivec3& halved, int32_t py, int32_t pz, ChildRow&& childRow) {
    const Children cz = childrenOf(pz, fineSize.z, halved.z), cy = childrenOf(py, fineSize.y, halved.y);
    for (int32_t z = cz.first; z < cz.first + cz.count; ++z)
        for (int32_t y = cy.first; y < cy.first + cy.count; ++y) childRow(y, z);
    return cz.count * cy.count;
}

// The full-multigrid start's coarse Dirichlet values: per coarse cell the mean of its fixed
// children's values (0 where it has none), each sum from 0 over the children in z, y, x order.
// Coarse slices are independent, so two threads give the same bits.
void restrictFixedMean(const Level& fine, const std::vector<float>& values, const Box& coarse, std::vector<float>& out) {
    const Box& b = fine.box;
    const glm::ivec3 halved = halvedAxes(b);
    out.resize(coarse.cellCount()); // every value is written below
    forTwoSlabs(coarse.size.z, minSlicesForThreads(b.cellCount()), [&](int32_t z0, int32_t z1) {
        std::vector<float> sum(size_t(coarse.size.x));
        std::vector<int32_t> count(size_t(coarse.size.x));
        for (int32_t pz = z0; pz < z1; ++pz)
            for (int32_t py = 0; py < coarse.size.y; ++py) {
                std::fill(sum.begin(), sum.end(), 0.0f);
                std::fill(count.begin(), count.end(), 0);
                forChildRows(b.size, halved, py, pz, [&](int32_t y, int32_t z) {
                    const size_t i0 = b.index(0, y, z);
                    for (int32_t x = 0; x < b.size.x; ++x)
                        if (fine.fixed[i0 + size_t(x)]) {
                            sum[size_t(x >> halved.x)] += values[i0 + size_t(x)];
                            ++count[size_t(x >> halved.x)];
                        }
                });
                const size_t p0 = coarse.index(0, py, pz);
                for (int32_t px = 0; px < coarse.size.x; ++px)
                    out[p0 + size_t(px)] = count[size_t(px)] > 0 ? sum[size_t(px)] / float(count[size_t(px)]) : 0.0f;
            }
    });
}

// sum[px] += the fine values of px's children along x, in x order: fine[2 px], then fine[2 px + 1]
// (where it exists) on a halved axis, fine[px] on a kept one. Vectorisable.
VOXC_SIMD_KERNEL
void addChildren(const float* __restrict fine, int32_t n, int32_t halved, float* __restrict sum) {
    if (!halved) {
        for (int32_t x = 0; x < n; ++x) sum[x] += fine[x];
        return;
    }
    const int32_t pairs = n / 2;
    for (int32_t px = 0; px < pairs; ++px) {
        sum[px] += fine[2 * px];
        sum[px] += fine[2 * px + 1];
    }
    if (n & 1) sum[pairs] += fine[n - 1];
}

// The coarse right-hand side: per coarse cell the mean of its children's residuals (0 at fixed
// children), summed in z, y, x order like restrictFixedMean, with the coarse correction reset to 0.
// Coarse slices are independent, so two threads give the same bits.
void restrictResidual(const Level& fine, size_t c, bool zeroRhs, Level& coarse) {
    const Box& b = fine.box;
    const glm::ivec3 halved = halvedAxes(b);
    const Box& cb = coarse.box;
    const float* rhs = zeroRhs ? nullptr : fine.f[c].data();
    std::vector<float>& out = coarse.f[c];
    forTwoSlabs(cb.size.z, minSlicesForThreads(b.cellCount()), [&](int32_t z0, int32_t z1) {
        std::vector<float> residual(size_t(b.size.x)), sum(size_t(cb.size.x));
        for (int32_t pz = z0; pz < z1; ++pz)
            for (int32_t py = 0; py < cb.size.y; ++py) {
                std::fill(sum.begin(), sum.end(), 0.0f);
                const int32_t rows = forChildRows(b.size, halved, py, pz, [&](int32_t y, int32_t z) {
                    residualRow(fine, fine.u[c], rhs, y, z, residual.data());
                    atHostSimd<addChildren>(residual.data(), b.size.x, halved.x, sum.data());
                });
                // Each coarse cell's child count: its z and y children (rows) times its x children.
                const size_t p0 = cb.index(0, py, pz);
                for (int32_t px = 0; px < cb.size.x; ++px)
                    out[p0 + size_t(px)] = sum[size_t(px)] / float(rows * childrenOf(px, b.size.x, halved.x).count);
            }
    });
}

// One V(3,3) cycle from level l down; the finest level's right-hand side is 0 (zeroRhs). With
// `measure`, returns level l's max residual with f = 0 at its end (maxResidualOf), measured in
// the pass of its last sweeps; otherwise 0.
float vCycle(std::vector<Level>& levels, size_t l, bool measure = true) {
    Level& level = levels[l];
    const bool zeroRhs = l == 0;
    float residual = 0.0f;
    float* measured = measure ? &residual : nullptr;
    if (l + 1 == levels.size()) {
        smooth(level, kCoarsestSweeps, zeroRhs, nullptr, measured);
        return residual;
    }
    smooth(level, kPreSmooth, zeroRhs);
    Level& coarse = levels[l + 1];
    for (size_t c = 0; c < level.u.size(); ++c) {
        restrictResidual(level, c, zeroRhs, coarse);
        std::fill(coarse.u[c].begin(), coarse.u[c].end(), 0.0f);
    }
    vCycle(levels, l + 1, false);
    const Prolongation prolongation(coarse.box, level);
    for (size_t c = 0; c < level.u.size(); ++c) prolongation.prepare(coarse.u[c], level.alongX[c]);
    const Correction correction{prolongation};
    smooth(level, kPostSmooth, zeroRhs, &correction, measured);
    return residual;
}

// max over free cells and components of |r| with f = 0 (a max is order-free: two threads give
// the same value).
float maxResidualOf(const Level& level) {
    const Box& b = level.box;
    float worst[2] = {0.0f, 0.0f};
    forTwoSlabs(b.size.z, minSlicesForThreads(b.cellCount()), [&](int32_t z0, int32_t z1) {
        std::vector<float> residual(size_t(b.size.x));
        float& w = worst[z0 == 0 ? 0 : 1];
        for (const std::vector<float>& u : level.u)
            for (int32_t z = z0; z < z1; ++z) w = maxResidualOfSlice(level, u, z, residual.data(), w);
    });
    return std::max(worst[0], worst[1]);
}

} // namespace

std::vector<MultigridLevel> multigridLevels(glm::ivec3 size) {
    std::vector<MultigridLevel> levels{MultigridLevel{size, halvedAxes(Box{glm::ivec3(0), size}), glm::vec3(1.0f)}};
    glm::ivec3 scale(0);
    while (levels.back().halved != glm::ivec3(0)) {
        const glm::ivec3 halved = levels.back().halved;
        scale += halved;
        const glm::ivec3 coarse = (levels.back().size + halved) >> halved;
        const glm::vec3 weight(std::ldexp(1.0f, -2 * scale.x), std::ldexp(1.0f, -2 * scale.y), std::ldexp(1.0f, -2 * scale.z));
        levels.push_back(MultigridLevel{coarse, halvedAxes(Box{glm::ivec3(0), coarse}), weight});
    }
    return levels;
}

namespace {

// multigridMasks without the finest level's (`fixed` itself): masks[l - 1] is level l's.
std::vector<std::vector<uint8_t>> coarserMasks(const std::vector<MultigridLevel>& levels,
                                               const std::vector<uint8_t>& fixed) {
    std::vector<std::vector<uint8_t>> masks;
    for (size_t l = 1; l < levels.size(); ++l) {
        const Box fine{glm::ivec3(0), levels[l - 1].size}, coarse{glm::ivec3(0), levels[l].size};
        const glm::ivec3 halved = levels[l - 1].halved;
        std::vector<uint8_t> mask(coarse.cellCount());
        const std::vector<uint8_t>& finer = masks.empty() ? fixed : masks.back();
        // A coarse cell is fixed where any child is; coarse slices are independent.
        forTwoSlabs(coarse.size.z, minSlicesForThreads(fine.cellCount()), [&](int32_t z0, int32_t z1) {
            for (int32_t pz = z0; pz < z1; ++pz)
                for (int32_t py = 0; py < coarse.size.y; ++py) {
                    uint8_t* out = mask.data() + coarse.index(0, py, pz);
                    std::fill(out, out + coarse.size.x, uint8_t(0));
                    forChildRows(fine.size, halved, py, pz, [&](int32_t y, int32_t z) {
                        const uint8_t* row = finer.data() + fine.index(0, y, z);
                        for (int32_t x = 0; x < fine.size.x; ++x) out[x >> halved.x] |= uint8_t(row[x] != 0);
                    });
                }
        });
        masks.push_back(std::move(mask));
    }
    return masks;
}

} // namespace

std::vector<std::vector<uint8_t>> multigridMasks(const std::vector<MultigridLevel>& levels,
                                                 const std::vector<uint8_t>& fixed) {
    std::vector<std::vector<uint8_t>> masks{fixed};
    for (std::vector<uint8_t>& mask : coarserMasks(levels, fixed)) masks.push_back(std::move(mask));
    return masks;
}

float maxResidual(const std::vector<uint8_t>& fixed, const Field3& u) {
    if (u.values.size() != fixed.size()) throw InternalError("curves: a residual with a mask of another size");
    Level level{u.box, glm::vec3(1.0f), fixed, {u.values}, {}, {}};
    return maxResidualOf(level);
}

SolveReport solveLaplace(const std::string& name, const std::vector<uint8_t>& fixed, std::vector<Field3*> components,
                         float tolerance, const Limits& limits) {
    return solveLaplaceUntilStopped(name, fixed, std::move(components), tolerance, limits, {});
}

SolveReport solveLaplaceUntilStopped(const std::string& name, const std::vector<uint8_t>& fixed,
                                     std::vector<Field3*> components, float tolerance, const Limits& limits,
                                     const std::stop_token& stop) {
    if (components.empty()) throw InternalError("curves: a linear solve without components");
    for (const Field3* c : components)
        if (c->box.size != components.front()->box.size || c->values.size() != fixed.size())
            throw InternalError("curves: the components and mask of a linear solve differ in size");
    const Box box{glm::ivec3(0), components.front()->box.size};
    const std::vector<MultigridLevel> shapes = multigridLevels(box.size);
    const std::vector<std::vector<uint8_t>> masks = coarserMasks(shapes, fixed);
    std::vector<Level> levels;
    for (size_t l = 0; l < shapes.size(); ++l)
        levels.push_back(Level{Box{glm::ivec3(0), shapes[l].size}, shapes[l].weight,
                               l == 0 ? std::span<const uint8_t>(fixed) : std::span<const uint8_t>(masks[l - 1]), {}, {}, {}});
    for (Level& level : levels) level.alongX.resize(components.size());

    // The finest unknowns go back into the components however the solve ends (a ConvergenceError
    // leaves the last iterate at the free cells); moves, not copies of whole fields.
    struct GiveBack {
        std::vector<Field3*>& components;
        std::vector<std::vector<float>>& finest;
        ~GiveBack() {
            for (size_t c = 0; c < components.size() && c < finest.size(); ++c) components[c]->values = std::move(finest[c]);
        }
    } giveBack{components, levels.front().u};
    // Full multigrid start: Dirichlet values restricted to every level (mean of the fixed
    // children), free cells 0; solve the coarsest, then prolongate and V-cycle level by level.
    for (Field3* component : components) {
        Level& top = levels.front();
        top.u.push_back(std::move(component->values)); // moved back on every way out (below)
        std::vector<float>& u = top.u.back();
        const size_t slice = size_t(box.size.x) * size_t(box.size.y);
        forTwoSlabs(box.size.z, minSlicesForThreads(box.cellCount()), [&](int32_t z0, int32_t z1) {
            for (size_t i = size_t(z0) * slice; i < size_t(z1) * slice; ++i) u[i] = top.fixed[i] ? u[i] : 0.0f;
        });
        top.f.emplace_back(); // the finest right-hand side is 0 and never read (zeroRhs)
        for (size_t l = 1; l < levels.size(); ++l) {
            const Level& fine = levels[l - 1];
            std::vector<float> values;
            restrictFixedMean(fine, fine.u.back(), levels[l].box, values);
            levels[l].u.push_back(std::move(values));
            levels[l].f.emplace_back(levels[l].box.cellCount(), 0.0f);
        }
    }
    // Each stage's residual is read only (maxResidualOf): the unknowns are those of an unrecorded
    // solve, bit for bit. A coarse level's right-hand side is still its start's 0 at its stage.
    std::vector<LevelResidual> stages;
    smooth(levels.back(), kCoarsestSweeps, levels.size() == 1);
    stages.push_back({levels.back().box.size, maxResidualOf(levels.back())});
    for (size_t l = levels.size() - 1; l-- > 0;) {
        throwIfStopped(stop);
        for (size_t c = 0; c < components.size(); ++c) prolong(levels[l + 1].box, levels[l + 1].u[c], levels[l], levels[l].u[c], false);
        stages.push_back({levels[l].box.size, vCycle(levels, l)});
    }

    SolveReport report{name, int32_t(levels.size()), {stages.back().residual}, std::move(stages)};
    while (!(report.residuals.back() <= tolerance)) {
        if (report.cycles() >= limits.maxCycles)
            throw ConvergenceError(name, report.cycles(), report.residuals.back(), tolerance);
        throwIfStopped(stop);
        report.residuals.push_back(vCycle(levels, 0));
    }
    return report;
}

} // namespace voxc::curves
