#include "voxc/generators/curves/Scene.h"

#include "HeapReuse.h"
#include "Parallel.h"

#include "voxc/builtins/Intervals.h"
#include "voxc/builtins/NoiseBatch.h"
#include "voxc/core/Errors.h"
#include "voxc/core/Simd.h"

#include <algorithm>
#include <array>
#include <glm/common.hpp>
#include <chrono>
#include <cmath>

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#include <immintrin.h>
#define VOXC_BAND_AVX512 1
#endif

namespace voxc::curves {

namespace {

bool namesMaterial(const Scene& scene) {
    if (!scene.inputs.empty() && scene.inputOptions.material != 0) return true;
    for (const FeatureCurve& curve : scene.curves)
        for (const ConstraintPoint& point : curve.constraints)
            if (point.material != 0) return true;
    return false;
}

// Where the noise displacement cannot change the density. The density clamp(0.5 - (S' - D) / 2,
// 0, 1) is 0 whenever the float d = S' - D is >= 1 and 1 whenever d <= -1 (d / 2 is exact and
// 0.5 - 0.5 rounds to +0, so the clamp returns the same bits as for any d past the bound). The
// float D = fl(alpha * w) has |D| <= |alpha| * |w| * (1 + 2^-24), and warped_fbm's range rule
// (voxc/builtins/Intervals.h: it bounds the interpreter's float result, rounding included) bounds
// |w| by W(r) for every roughness <= r. So with bound = |alpha| * W(r) * (1 + 2^-23) (the extra
// 2^-24 covers the double arithmetic here, which is exact to 1e-16), S' >= 1 + bound gives
// d >= 1 (rounding is monotone and 1 is a float) and S' <= -1 - bound gives d <= -1: such cells
// take the saturated value without evaluating the noise. W is tabulated for roughness up to
// b / kBuckets; a cell uses the bucket at or above its roughness.
class DisplacementBand {
public:
    static constexpr int32_t kBuckets = 64;

    DisplacementBand(const Box& box, float frequency, uint32_t seed) {
        const RangeRule rule = rangeRule("warped_fbm");
        VOXC_ASSERT(rule != nullptr);
        Interval args[5];
        // p = float(voxel) * f0 lies between the rounded products at the box corners (f0 >= 0).
        const glm::dvec3 lo = glm::dvec3(glm::vec3(box.min) * frequency);
        const glm::dvec3 hi = glm::dvec3(glm::vec3(box.min + box.size - 1) * frequency);
        args[0] = Interval{Type::Vec3, glm::min(lo, hi), glm::max(lo, hi), false};
        args[2] = args[3] = Interval::point(Type::Float, glm::dvec3(0.0));
        args[4] = Interval::point(Type::Int, glm::dvec3(double(seed)));
        for (int32_t b = 0; b <= kBuckets; ++b) {
            args[1] = Interval{Type::Float, glm::dvec3(-1.0), glm::dvec3(double(b) / kBuckets), false};
            const Interval w = rule(std::span<const Interval>(args));
            const double bound = std::max(std::fabs(w.lo.x), std::fabs(w.hi.x));
            bound_[size_t(b)] = std::isfinite(bound) ? bound * (1.0 + 0x1p-23) : INFINITY;
        }
    }

    // The saturated density of each of a row's n cells into out, or -1 where the noise must be
    // evaluated (the row's smoothed S', amplitude and roughness): eight cells per AVX-512 register
    // where the CPU has it, with the same double operations per cell (the bound a gather).
    void saturatedRow(const float* smoothed, const float* alpha, const float* roughness, size_t n, float* out) const {
        size_t x = 0;
#ifdef VOXC_BAND_AVX512
        if (hostSimd() == Simd::Avx512) x = saturatedAvx512(bound_.data(), smoothed, alpha, roughness, n, out);
#endif
        for (; x < n; ++x) out[x] = saturated(smoothed[x], alpha[x], roughness[x]);
    }

private:
    float saturated(float smoothed, float alpha, float roughness) const {
        if (!(roughness >= -1.0f && roughness <= 1.0f)) return -1.0f;
        const double bound = std::fabs(double(alpha)) * bound_[size_t(std::ceil(std::max(0.0, double(roughness) * kBuckets)))];
        if (double(smoothed) >= 1.0 + bound) return 0.0f;
        if (double(smoothed) <= -1.0 - bound) return 1.0f;
        return -1.0f;
    }

#ifdef VOXC_BAND_AVX512
    // saturated() over the row's whole registers of eight cells; returns how many cells it did. A
    // lane outside [-1, 1] (or NaN) reads bucket 0 and returns -1, as the scalar test does first;
    // max(0, r * 64) is the scalar std::max's value (r * 64 > 0 ? r * 64 : 0), then ceil, the
    // gather, |alpha| * bound, 1 + bound and -1 - bound, each rounded as the scalar operation. (The
    // maskz forms with every lane set: GCC 12's plain forms warn of their undefined source.)
    __attribute__((target("avx512f,avx512vl,avx512dq"))) static size_t
    saturatedAvx512(const double* bounds, const float* smoothed, const float* alpha, const float* roughness, size_t n,
                    float* out) {
        size_t x = 0;
        for (; x + 8 <= n; x += 8) {
            const __m256 r = _mm256_loadu_ps(roughness + x);
            const __mmask8 valid = __mmask8(_mm256_cmp_ps_mask(r, _mm256_set1_ps(-1.0f), _CMP_GE_OQ) &
                                            _mm256_cmp_ps_mask(r, _mm256_set1_ps(1.0f), _CMP_LE_OQ));
            const __m512d scaled = _mm512_maskz_mul_pd(valid, _mm512_maskz_cvtps_pd(0xff, r), _mm512_set1_pd(double(kBuckets)));
            const __m512d above = _mm512_maskz_roundscale_pd(0xff, _mm512_maskz_max_pd(0xff, scaled, _mm512_setzero_pd()),
                                                             _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC);
            const __m256i bucket = _mm512_maskz_cvttpd_epi32(0xff, above);
            const __m512d table = _mm512_mask_i32gather_pd(_mm512_setzero_pd(), 0xff, bucket, bounds, 8);
            const __m512d magnitude = _mm512_abs_pd(_mm512_maskz_cvtps_pd(0xff, _mm256_loadu_ps(alpha + x)));
            const __m512d bound = _mm512_mul_pd(magnitude, table);
            const __m512d s = _mm512_maskz_cvtps_pd(0xff, _mm256_loadu_ps(smoothed + x));
            const __mmask8 empty = _mm512_cmp_pd_mask(s, _mm512_add_pd(_mm512_set1_pd(1.0), bound), _CMP_GE_OQ);
            const __mmask8 full = _mm512_cmp_pd_mask(s, _mm512_sub_pd(_mm512_set1_pd(-1.0), bound), _CMP_LE_OQ);
            __m256 result = _mm256_set1_ps(-1.0f);
            result = _mm256_mask_blend_ps(__mmask8(valid & full), result, _mm256_set1_ps(1.0f));
            result = _mm256_mask_blend_ps(__mmask8(valid & empty), result, _mm256_setzero_ps());
            _mm256_storeu_ps(out + x, result);
        }
        return x;
    }
#endif

    std::array<double, kBuckets + 1> bound_{};
};

} // namespace

SolveTable solveScene(const Scene& scene, const Limits& limits, const Solvers& solvers, bool keepChannels) {
    const FieldHeapReuse reuse(scene.box.cellCount()); // the solve's freed fields serve its next ones (HeapReuse.h)
    Result solved = scene.gathered ? solveCurves(Constraints(*scene.gathered), scene.options, limits, solvers)
                    : scene.inputs.empty()
                        ? runCurves(scene.curves, scene.box, scene.options, limits, solvers)
                        : solveCurves(voxelize(scene.curves, scene.box, scene.options.seedValue, limits, scene.inputs,
                                               scene.inputOptions),
                                      scene.options, limits, solvers);
    throwIfStopped(solvers.stop);
    const auto densityStart = std::chrono::steady_clock::now();
    if (!keepChannels) {
        // What the density does not read goes back to the heap before the table is allocated, so
        // the table takes its memory instead of fresh pages (HeapReuse.h).
        solved.normalX = {}, solved.normalY = {}, solved.normalZ = {};
        solved.surface = {};
        solved.material.confidence = {}, solved.material.assigned = {};
    }
    const Box& box = scene.box;
    const DisplacementBand band(box, scene.noiseFrequency, scene.noiseSeed);
    SolveTable table;
    table.min = box.min;
    table.size = box.size;
    table.density.resize(box.cellCount());
    const bool materials = namesMaterial(scene);
    if (materials) table.material.resize(box.cellCount());
    // A device evaluates the displacement at every cell, in one pass; the host only in the band.
    std::vector<float> displacements;
    if (solvers.displacement)
        displacements = solvers.displacement(solved.amplitude, solved.roughness, scene.noiseFrequency, scene.noiseSeed);
    const bool displaced = !displacements.empty();
    if (!displaced && keepChannels) displacements.assign(box.cellCount(), 0.0f);
    const bool everyCell = keepChannels || displaced;
    // Pointwise: each cell's value depends on that cell alone, so two threads give the same bits.
    // Per slice, the cells whose displacement must be evaluated are gathered and evaluated together
    // (warpedFbmBatch: the builtin's own values bit for bit, eight cells per AVX2 register, sixteen
    // per AVX-512 one; a batch per slice leaves one part-filled register where a batch per row
    // left one or two, in the narrower form).
    forTwoSlabs(box.size.z, 8, [&](int32_t z0, int32_t z1) {
        const size_t n = size_t(box.size.x) * size_t(box.size.y);
        std::vector<float> px(n), py(n), pz(n), roughness(n), noise(n);
        std::vector<size_t> pending(n);
        std::vector<float> saturatedRow(everyCell ? 0 : size_t(box.size.x));
        // The density of a cell with displacement D, and its material.
        auto finish = [&](size_t i, float s, float displacement) {
            if (keepChannels && !displaced) displacements[i] = displacement;
            const float d = s - displacement;
            // +infinity: no seed reaches the cell, so it is air.
            const float density = d < INFINITY ? std::clamp(0.5f - d / 2.0f, 0.0f, 1.0f) : 0.0f;
            table.density[i] = density;
            if (materials && density >= 0.5f) table.material[i] = uint8_t(solved.material.material[i]);
        };
        for (int32_t z = z0; z < z1; ++z) {
            size_t count = 0;
            for (int32_t y = 0; y < box.size.y; ++y) {
                const size_t row = box.index(0, y, z);
                if (!everyCell)
                    band.saturatedRow(solved.smoothed.values.data() + row, solved.amplitude.values.data() + row,
                                      solved.roughness.values.data() + row, size_t(box.size.x), saturatedRow.data());
                for (int32_t x = 0; x < box.size.x; ++x) {
                    const size_t i = row + size_t(x);
                    const float s = solved.smoothed.values[i];
                    const float alpha = solved.amplitude.values[i];
                    // With keepChannels every cell's displacement is evaluated (the dump shows it), and
                    // the densities are the same bits (DisplacementBand).
                    const float saturated = everyCell ? -1.0f : saturatedRow[size_t(x)];
                    if (saturated >= 0.0f) {
                        table.density[i] = saturated;
                        if (materials && saturated >= 0.5f) table.material[i] = uint8_t(solved.material.material[i]);
                    } else if (alpha != 0.0f && !displaced) {
                        const glm::vec3 p = glm::vec3(box.min + glm::ivec3(x, y, z)) * scene.noiseFrequency;
                        px[count] = p.x, py[count] = p.y, pz[count] = p.z;
                        roughness[count] = solved.roughness.values[i];
                        pending[count++] = i;
                    } else {
                        finish(i, s, displaced ? displacements[i] : 0.0f);
                    }
                }
            }
            warpedFbmBatch(px.data(), py.data(), pz.data(), roughness.data(), 0.0f, 0.0f, scene.noiseSeed, count,
                           noise.data());
            for (size_t c = 0; c < count; ++c) {
                const size_t i = pending[c];
                finish(i, solved.smoothed.values[i], solved.amplitude.values[i] * noise[c]);
            }
        }
    });
    if (keepChannels) {
        std::vector<float> material(box.cellCount()), confidence = std::move(solved.material.confidence.values);
        for (size_t i = 0; i < material.size(); ++i) material[i] = float(solved.material.material[i]);
        table.channels = {{"normal_x", std::move(solved.normalX.values)},  {"normal_y", std::move(solved.normalY.values)},
                          {"normal_z", std::move(solved.normalZ.values)},  {"amplitude", std::move(solved.amplitude.values)},
                          {"roughness", std::move(solved.roughness.values)}, {"material", std::move(material)},
                          {"confidence", std::move(confidence)},         {"distance", std::move(solved.surface.distance.values)},
                          {"smoothed", std::move(solved.smoothed.values)}, {"displacement", std::move(displacements)}};
    }
    table.phaseMs = solved.phaseMs;
    table.phaseMs.emplace_back(
        "density", std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - densityStart).count());
    for (const SolveReport& report : solved.solves)
        table.solves.push_back({report.name, report.levels, report.residuals, report.fullMultigrid});
    return table;
}

} // namespace voxc::curves
