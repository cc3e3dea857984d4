// Range rules of the noise builtins: bounds proved from the implementations
// (compiler/builtins/src/functions), not sampled extremes.
#include "IntervalMath.h"

#include <algorithm>
#include <cmath>

namespace voxc::intervals {

namespace {

// ---- Noise (p must be finite: floor(inf) - inf is NaN) ----
//
// perlin3: the value is sum_c W_c (g_c . d_c) over the cell's 8 corners, W_c = products of
// fade(x) or 1 - fade(x) per axis (non-negative, summing to 1), d_c the offset to corner c and
// g_c one of Perlin's 12 edge gradients, two entries +-1 and one 0, so |g_c . d_c| <= |dx| + |dy|
// + |dz|. Along x the weighted offsets sum to (1 - fade(x)) x + fade(x) (1 - x) <= 1/2 (fade(x)
// <= x below 1/2, symmetric above), so |perlin3| <= 3/2. The same sum bounds the derivative:
// |d/dx| <= fade'(x) * (1 + 2 (1/2 + 1/2)) + 1 <= 1.875 * 3 + 1 (fade' <= 30/16).
constexpr double kPerlinBound = 1.5, kPerlinSlope = 6.625;
// Float error of one lattice-noise evaluation (about 40 roundings of values below 16, each at
// most 2^-24 relative, is below 4e-5) plus the records' GPU tolerance (1e-6).
constexpr double kNoiseSlack = 1e-4;
// simplex3: 76 * sum of 4 corners (0.5 - r^2)^4 (g . d) with |g . d| <= sqrt(2) r; the corner
// term peaks at r^2 = 1/18 with (4/9)^4 / 3, so |simplex3| <= 4 * 76 * 256 / 19683 ~ 3.954.
constexpr double kSimplexBound = 4.0 * 76.0 * 256.0 / 19683.0;
// worley: the point's own cell holds a feature point with every offset below 1 (F1 <= sqrt 3);
// the neighbour across the nearer x face holds one with offsets below (1.5, 1, 1), so the second
// nearest is at most sqrt(4.25) away.
const double kWorleyF1Bound = std::sqrt(3.0), kWorleyF2Bound = std::sqrt(4.25);
// Float-finite results need finite products: bounds above this count as overflow.
constexpr double kOverflow = 1e30;

Interval symmetric(double bound) { return floatInterval(-bound, bound); }
bool finitePoint(const Interval& p) { return p.type == Type::Vec3 && finite(p); }

Interval perlinRule(std::span<const Interval> a) {
    return finitePoint(a[0]) ? symmetric(kPerlinBound + kNoiseSlack) : Interval::unknown(Type::Float);
}
// The skew (p.x + p.y + p.z) / 3 added to a coordinate overflows, giving NaN, only past a
// quarter of the float range.
Interval simplexRule(std::span<const Interval> a) {
    const bool skewFits = finitePoint(a[0]) && maxAbs(a[0]) * 4 < kFloatMax;
    return skewFits ? symmetric(kSimplexBound + kNoiseSlack) : Interval::unknown(Type::Float);
}
Interval valueRule(std::span<const Interval> a) { // lattice values in [-1, 1), interpolated
    return finitePoint(a[0]) ? symmetric(1.0 + kNoiseSlack) : Interval::unknown(Type::Float);
}
template <int Which> // 0: F1, 1: F2, 2: F2 - F1 (>= 0 as F2 >= F1), 3: (F1, F2)
Interval worleyRule(std::span<const Interval> a) {
    if (!finitePoint(a[0])) return Interval::unknown(Which == 3 ? Type::Vec2 : Type::Float); // NaN offsets give 10
    const double f1 = kWorleyF1Bound + kNoiseSlack, f2 = kWorleyF2Bound + kNoiseSlack;
    if (Which == 3) return {Type::Vec2, {-kNoiseSlack, -kNoiseSlack, 0}, {f1, f2, 0}, false};
    return floatInterval(-kNoiseSlack, Which == 0 ? f1 : f2);
}

// curl3: each component is a difference of two central differences (n(a) - n(b)) * 128, with
// a = p + eps and b = p - eps rounded (apart by at most 2 eps + (|p| + eps) 2^-23): by the mean
// value theorem each is at most 128 min(2 * 1.5, slope |a - b|), plus the evaluations' error.
Interval curlRule(std::span<const Interval> a) {
    if (!finitePoint(a[0])) return Interval::unknown(Type::Vec3);
    const double eps = 1.0 / 256.0, step = 2.0 * eps + (maxAbs(a[0]) + eps) * 0x1p-23;
    const double quotient = 128.0 * (std::min(2.0 * kPerlinBound, kPerlinSlope * step) + 2.0 * kNoiseSlack);
    const double bound = up(2.0 * quotient);
    return {Type::Vec3, glm::dvec3(-bound), glm::dvec3(bound), false};
}

// Fractals fbm(p, octaves, lacunarity, gain, seed): octave k has amplitude gain^k (a running
// float product) and frequency lacunarity^k. `sum` bounds sum_k |amplitude_k| over the octaves,
// or is infinite where a float product could overflow (inf * 0 is NaN).
struct Octaves {
    double sum = kInf;
    bool nonNegativeGain = false;
};
Octaves octaves(std::span<const Interval> a) {
    Octaves o;
    if (!finitePoint(a[0]) || !finite(a[2]) || !finite(a[3])) return o;
    const int count = int(std::clamp(a[1].hi.x, 1.0, 16.0)); // the sum grows with the count
    const double gain = std::max(std::fabs(a[3].lo.x), std::fabs(a[3].hi.x)) * (1 + 1e-6);
    const double lacunarity = std::max({1.0, std::fabs(a[2].lo.x), std::fabs(a[2].hi.x)}) * (1 + 1e-6);
    double sum = 0, amplitude = 1, frequency = maxAbs(a[0]) + 1;
    for (int k = 0; k < count; ++k, amplitude *= gain, frequency *= lacunarity) {
        if (amplitude > kOverflow || frequency > kOverflow) return o;
        sum += amplitude;
    }
    o.sum = sum;
    o.nonNegativeGain = a[3].lo.x >= 0.0;
    return o;
}
// Each octave's term lies in [termLo, termHi]; the float sum's roundings are relative.
Interval octaveSum(const Octaves& o, double termLo, double termHi) {
    if (o.sum == kInf) return Interval::unknown(Type::Float);
    const double lo = o.nonNegativeGain ? o.sum * std::min(termLo, 0.0) : -o.sum * std::max(-termLo, termHi);
    const double hi = o.nonNegativeGain ? o.sum * termHi : o.sum * std::max(-termLo, termHi);
    return widened(floatInterval(lo, hi), kNoiseSlack, 1e-5);
}
constexpr double kNoiseMax = kPerlinBound + kNoiseSlack;
Interval fbmRule(std::span<const Interval> a) { return octaveSum(octaves(a), -kNoiseMax, kNoiseMax); }
Interval turbulenceRule(std::span<const Interval> a) { return octaveSum(octaves(a), 0.0, kNoiseMax); }
// ridged: s_k = (1 - |n_k|)^2 w_k with |n_k| <= 1.5 and w_k in [0, 1], so s_k is in [0, 1].
Interval ridgedRule(std::span<const Interval> a) { return octaveSum(octaves(a), 0.0, 1.0 + 1e-6); }

// warp(p, amount, seed) = p + amount * w per axis, w an fbm of 4 octaves with gain 1/2:
// |w| <= 1.875 * 1.5 (octave frequencies up to 8).
Interval warpRule(std::span<const Interval> a) {
    if (!finitePoint(a[0]) || !finite(a[1]) || maxAbs(a[0]) * 8 > kOverflow) return Interval::unknown(Type::Vec3);
    const Interval scaled[] = {a[1], symmetric(up(1.875 * kNoiseMax))};
    const Interval sum[] = {a[0], mul(scaled)};
    return widened(add(sum), 1e-6, 0.0);
}

// warped_fbm: sum over k = 0..4 of a^k perlin3(...), a = 2^-(1 - roughness) (one exp2, within
// 3 + 2|1 - R| ulp on the GPU); inner points q + w * offset with |q| <= 16 |p|, |w| <= 4|F| + |D|.
Interval warpedFbmRule(std::span<const Interval> a) {
    const bool full = a.size() == 5;
    for (size_t i = 0; i + 1 < a.size(); ++i)
        if (!finite(a[i])) return Interval::unknown(Type::Float);
    const double roughness = full ? a[1].hi.x : 0.0;
    const double warpBound = full ? 4 * std::max(std::fabs(a[3].lo.x), std::fabs(a[3].hi.x)) +
                                        std::max(std::fabs(a[2].lo.x), std::fabs(a[2].hi.x))
                                  : 3.0;
    const double ratio = std::exp2(roughness - 1.0) * (1 + (4 + 2 * std::fabs(1 - roughness)) * 0x1p-23 + 1e-6);
    double sum = 0, amplitude = 1;
    for (int k = 0; k <= 4; ++k, amplitude *= ratio) sum += amplitude;
    if (!(sum < kOverflow) || 16 * maxAbs(a[0]) + warpBound * kNoiseMax > kOverflow) return Interval::unknown(Type::Float);
    return widened(symmetric(sum * kNoiseMax), 1e-5, 1e-5);
}

const NamedRule kNoiseRules[] = {
    {"perlin3", perlinRule}, {"simplex3", simplexRule}, {"value3", valueRule},
    {"worley3", worleyRule<3>}, {"worley_f1", worleyRule<0>}, {"worley_f2", worleyRule<1>},
    {"worley_f2f1", worleyRule<2>}, {"curl3", curlRule},
    {"fbm", fbmRule}, {"ridged", ridgedRule}, {"turbulence", turbulenceRule},
    {"warp", warpRule}, {"warped_fbm", warpedFbmRule},
};

} // namespace

std::span<const NamedRule> noiseRules() { return kNoiseRules; }

} // namespace voxc::intervals
