#include "voxc/builtins/Intervals.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <unordered_map>

namespace voxc {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// One float rounding is at most 2^-24 relative; 1e-6 also covers the double arithmetic of the
// bounds. kTiny covers results that round to or from subnormals.
constexpr double kRelative = 1e-6, kTiny = 1e-36;
constexpr double kFloatMax = std::numeric_limits<float>::max();
// The records' GPU tolerances (compiler/builtins/src/functions), added to rules of functions
// that are not bit-exact on the GPU.
constexpr double kSqrtTolerance = 4e-5, kPowTolerance = 2e-3, kTrigTolerance = 4.8828125e-4,
                 kPlaneTolerance = 1e-4, kSmoothTolerance = 5e-5;

int components(Type t) { return t == Type::Vec3 ? 3 : t == Type::Vec2 ? 2 : 1; }
bool isFloatLike(Type t) { return t == Type::Float || t == Type::Vec2 || t == Type::Vec3; }

// Outward by one rounding; past the float range the float result may be infinite.
double down(double x) {
    const double r = std::isnan(x) ? -kInf : x - std::fabs(x) * kRelative - kTiny;
    return r < -kFloatMax ? -kInf : r;
}
double up(double x) {
    const double r = std::isnan(x) ? kInf : x + std::fabs(x) * kRelative + kTiny;
    return r > kFloatMax ? kInf : r;
}

// Component c of an operand, a float broadcast to every component.
double lo(const Interval& a, int c) { return a.type == Type::Float ? a.lo.x : a.lo[c]; }
double hi(const Interval& a, int c) { return a.type == Type::Float ? a.hi.x : a.hi[c]; }

Interval floatInterval(double l, double h) { return {Type::Float, {l, 0, 0}, {h, 0, 0}, false}; }

bool finite(const Interval& a) {
    for (int c = 0; c < components(a.type); ++c)
        if (!std::isfinite(a.lo[c]) || !std::isfinite(a.hi[c])) return false;
    return true;
}
double maxAbs(const Interval& a) {
    double m = 0;
    for (int c = 0; c < components(a.type); ++c) m = std::max({m, std::fabs(a.lo[c]), std::fabs(a.hi[c])});
    return m;
}
// Outward by `absolute` plus `relative` of each bound's magnitude (never exact).
Interval widened(Interval r, double absolute, double relative) {
    for (int c = 0; c < components(r.type); ++c) {
        r.lo[c] = down(r.lo[c] - absolute - std::fabs(r.lo[c]) * relative);
        r.hi[c] = up(r.hi[c] + absolute + std::fabs(r.hi[c]) * relative);
    }
    r.exact = false;
    return r;
}
Interval boolInterval(bool canBeFalse, bool canBeTrue) {
    Interval r{Type::Bool, {canBeTrue && !canBeFalse ? 1.0 : 0.0, 0, 0}, {canBeTrue ? 1.0 : 0.0, 0, 0}, false};
    r.exact = canBeFalse != canBeTrue;
    return r;
}

// Component-wise arithmetic: `corners` gives the exact result's bounds from the operand bounds
// (NaN bounds, e.g. inf * 0, become unknown); the result is widened by one rounding.
template <typename Corners>
Interval arithmetic(std::span<const Interval> a, Corners corners) {
    Type type = Type::Float;
    for (const Interval& x : a) {
        if (!isFloatLike(x.type)) return Interval::unknown(a[0].type);
        if (x.type != Type::Float) type = x.type;
    }
    Interval r{type, glm::dvec3(0.0), glm::dvec3(0.0), false};
    for (int c = 0; c < components(type); ++c) {
        auto [l, h] = corners(a, c);
        r.lo[c] = down(l);
        r.hi[c] = up(h);
    }
    return r;
}

std::pair<double, double> hullOf(std::initializer_list<double> values) {
    double l = kInf, h = -kInf;
    for (double v : values) {
        if (std::isnan(v)) return {-kInf, kInf};
        l = std::min(l, v);
        h = std::max(h, v);
    }
    return {l, h};
}

Interval add(std::span<const Interval> a) {
    return arithmetic(a, [](auto a, int c) { return std::pair{lo(a[0], c) + lo(a[1], c), hi(a[0], c) + hi(a[1], c)}; });
}
Interval sub(std::span<const Interval> a) {
    return arithmetic(a, [](auto a, int c) { return std::pair{lo(a[0], c) - hi(a[1], c), hi(a[0], c) - lo(a[1], c)}; });
}
Interval mul(std::span<const Interval> a) {
    return arithmetic(a, [](auto a, int c) {
        const double l0 = lo(a[0], c), h0 = hi(a[0], c), l1 = lo(a[1], c), h1 = hi(a[1], c);
        return hullOf({l0 * l1, l0 * h1, h0 * l1, h0 * h1});
    });
}
Interval div(std::span<const Interval> a) {
    return arithmetic(a, [](auto a, int c) {
        const double l0 = lo(a[0], c), h0 = hi(a[0], c), l1 = lo(a[1], c), h1 = hi(a[1], c);
        if (l1 <= 0.0 && h1 >= 0.0) return std::pair{-kInf, kInf};
        return hullOf({l0 / l1, l0 / h1, h0 / l1, h0 / h1});
    });
}

// Negation is exact.
Interval neg(std::span<const Interval> a) {
    if (!isFloatLike(a[0].type)) return Interval::unknown(a[0].type);
    return {a[0].type, -a[0].hi, -a[0].lo, a[0].exact};
}

// GLSL min(a, b) = b < a ? b : a and max(a, b) = a < b ? b : a: when the operands are strictly
// ordered the result is one operand (exactly); otherwise min/max of the ends bound it.
Interval pick(const Interval& a, const Interval& b, bool maximum) {
    if (a.type != Type::Float || b.type != Type::Float) return Interval::unknown(Type::Float);
    if (a.hi.x < b.lo.x) return maximum ? b : a;
    if (b.hi.x < a.lo.x) return maximum ? a : b;
    if (maximum) return floatInterval(std::max(a.lo.x, b.lo.x), std::max(a.hi.x, b.hi.x));
    return floatInterval(std::min(a.lo.x, b.lo.x), std::min(a.hi.x, b.hi.x));
}
Interval minRule(std::span<const Interval> a) { return pick(a[0], a[1], false); }
Interval maxRule(std::span<const Interval> a) { return pick(a[0], a[1], true); }
Interval clampRule(std::span<const Interval> a) { return pick(pick(a[0], a[1], true), a[2], false); }
Interval subtractRule(std::span<const Interval> a) { // max(a, -b)
    const Interval negB = neg(a.subspan(1, 1));
    return pick(a[0], negB, true);
}

Interval absRule(std::span<const Interval> a) {
    if (a[0].type != Type::Float) return Interval::unknown(a[0].type);
    const double l = a[0].lo.x, h = a[0].hi.x;
    Interval r = floatInterval(l >= 0 ? l : h <= 0 ? -h : 0.0, std::max(std::fabs(l), std::fabs(h)));
    if (a[0].exact) r = Interval::point(Type::Float, {std::fabs(l), 0, 0});
    return r;
}
Interval floorRule(std::span<const Interval> a) {
    if (a[0].type != Type::Float) return Interval::unknown(a[0].type);
    Interval r = floatInterval(std::floor(a[0].lo.x), std::floor(a[0].hi.x));
    r.exact = a[0].exact;
    return r;
}

Interval vecRule(std::span<const Interval> a) {
    Interval r{a.size() == 3 ? Type::Vec3 : Type::Vec2, glm::dvec3(0.0), glm::dvec3(0.0), true};
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i].type != Type::Float) return Interval::unknown(r.type);
        r.lo[int(i)] = a[i].lo.x;
        r.hi[int(i)] = a[i].hi.x;
        r.exact = r.exact && a[i].exact;
    }
    return r;
}

// Bounds of x * y summed over components (exact reals), for dot and length.
std::pair<double, double> dotBounds(const Interval& a, const Interval& b) {
    double l = 0, h = 0;
    for (int c = 0; c < components(a.type); ++c) {
        auto [pl, ph] = hullOf({a.lo[c] * b.lo[c], a.lo[c] * b.hi[c], a.hi[c] * b.lo[c], a.hi[c] * b.hi[c]});
        l += pl;
        h += ph;
    }
    return {l, h};
}
double squaredGap(double l, double h) { return l > 0 ? l * l : h < 0 ? h * h : 0.0; }
double downBy(double x, int steps) { for (int i = 0; i < steps; ++i) x = down(x); return x; }
double upBy(double x, int steps) { for (int i = 0; i < steps; ++i) x = up(x); return x; }

// Each float step of the sum rounds by at most 2^-24 of the terms' magnitude (the sum itself may
// cancel to far less); a partial sum past the float range may be infinite.
Interval dotRule(std::span<const Interval> a) {
    if (!isFloatLike(a[0].type) || a[0].type == Type::Float || a[0].type != a[1].type)
        return Interval::unknown(Type::Float);
    auto [l, h] = dotBounds(a[0], a[1]);
    double magnitude = 0;
    for (int c = 0; c < components(a[0].type); ++c)
        magnitude += std::max({std::fabs(a[0].lo[c]), std::fabs(a[0].hi[c])}) *
                     std::max({std::fabs(a[1].lo[c]), std::fabs(a[1].hi[c])});
    if (!(magnitude < kFloatMax * 0.5)) return Interval::unknown(Type::Float);
    const double slack = magnitude * 1e-6 + 8 * kTiny;
    return floatInterval(down(l - slack), up(h + slack));
}
// Squares below the float normal range lose precision (so the float length of a tiny vector
// may be 0); a sum of squares past the float range is infinite.
Interval lengthRule(std::span<const Interval> a) {
    if (a[0].type == Type::Float || !isFloatLike(a[0].type)) return Interval::unknown(Type::Float);
    double l = 0, h = 0;
    for (int c = 0; c < components(a[0].type); ++c) {
        l += squaredGap(a[0].lo[c], a[0].hi[c]);
        h += std::max(a[0].lo[c] * a[0].lo[c], a[0].hi[c] * a[0].hi[c]);
    }
    const double lower = l < 1e-30 ? 0.0 : std::max(0.0, downBy(std::sqrt(l), 8));
    return floatInterval(lower, h > kFloatMax * 0.5 ? kInf : upBy(std::sqrt(h), 8));
}

// Signed distances: the lower bound is the gap between the position box and the primitive's
// bounding box (minus the radius); the upper bound is the largest distance from the box's
// corners to the primitive minus the radius, valid because the distance to a convex set is
// convex in p. `margin` covers the float evaluation's roundings (about 20 steps of 2^-24
// relative to the coordinates' magnitude).
double margin(std::initializer_list<const Interval*> args) {
    double scale = 1.0;
    for (const Interval* a : args)
        for (int c = 0; c < 3; ++c) scale = std::max({scale, std::fabs(a->lo[c]), std::fabs(a->hi[c])});
    return scale * 1e-5;
}
// Coordinates past ~1e18 (a margin of 1e13) have squares beyond the float range.
constexpr double kSquaresOverflow = 1e13;
double boxGap(const Interval& p, glm::dvec3 lo, glm::dvec3 hi) {
    double s = 0;
    for (int c = 0; c < 3; ++c) {
        const double gap = std::max({lo[c] - p.hi[c], p.lo[c] - hi[c], 0.0});
        s += gap * gap;
    }
    return std::sqrt(s);
}
template <typename Distance>
double cornerMax(const Interval& p, Distance distance) {
    double m = -kInf;
    for (int i = 0; i < 8; ++i)
        m = std::max(m, distance(glm::dvec3(i & 1 ? p.hi.x : p.lo.x, i & 2 ? p.hi.y : p.lo.y, i & 4 ? p.hi.z : p.lo.z)));
    return m;
}
bool vec3Args(std::span<const Interval> a, std::initializer_list<int> vecs) {
    for (int i : vecs) if (a[i].type != Type::Vec3) return false;
    return true;
}

Interval sphereRule(std::span<const Interval> a) {
    if (!vec3Args(a, {0, 1}) || a[2].type != Type::Float) return Interval::unknown(Type::Float);
    const double m = margin({&a[0], &a[1], &a[2]});
    if (!(m < kSquaresOverflow)) return Interval::unknown(Type::Float);
    const double l = boxGap(a[0], a[1].lo, a[1].hi) - a[2].hi.x - m;
    double h = kInf;
    if (a[1].exact && a[2].exact)
        h = cornerMax(a[0], [&](glm::dvec3 p) { return glm::length(p - a[1].lo); }) - a[2].lo.x + m;
    return floatInterval(l, h);
}

Interval capsuleRule(std::span<const Interval> a) {
    if (!vec3Args(a, {0, 1, 2}) || a[3].type != Type::Float) return Interval::unknown(Type::Float);
    const double m = margin({&a[0], &a[1], &a[2], &a[3]});
    if (!(m < kSquaresOverflow)) return Interval::unknown(Type::Float);
    const double l = boxGap(a[0], glm::min(a[1].lo, a[2].lo), glm::max(a[1].hi, a[2].hi)) - a[3].hi.x - m;
    double h = kInf;
    if (a[1].exact && a[2].exact && a[3].exact) {
        const glm::dvec3 s = a[1].lo, ba = a[2].lo - s;
        const double baba = glm::dot(ba, ba);
        h = cornerMax(a[0], [&](glm::dvec3 p) {
                const double t = baba > 0 ? std::clamp(glm::dot(p - s, ba) / baba, 0.0, 1.0) : 0.0;
                return glm::length(p - s - ba * t);
            }) - a[3].lo.x + m;
    }
    return floatInterval(l, h);
}

Interval boxRule(std::span<const Interval> a) {
    if (!vec3Args(a, {0, 1, 2})) return Interval::unknown(Type::Float);
    const double m = margin({&a[0], &a[1], &a[2]});
    if (!(m < kSquaresOverflow)) return Interval::unknown(Type::Float);
    glm::dvec3 half(0.0);
    for (int c = 0; c < 3; ++c) half[c] = std::max(std::fabs(a[2].lo[c]), std::fabs(a[2].hi[c]));
    const double gap = boxGap(a[0], a[1].lo - half, a[1].hi + half);
    const double l = (gap > 0 ? gap : -std::max({half.x, half.y, half.z})) - m;
    double h = kInf;
    if (a[1].exact && a[2].exact)
        h = cornerMax(a[0], [&](glm::dvec3 p) {
                const glm::dvec3 q = glm::abs(p - a[1].lo) - glm::abs(a[2].lo);
                return glm::length(glm::max(q, 0.0)) + std::min(std::max({q.x, q.y, q.z}), 0.0);
            }) + m;
    return floatInterval(l, h);
}

// density(d, width) = clamp(0.5 - d / width, 0, 1) for width > 0: exactly 0 where d / width
// is surely above 0.5, exactly 1 where surely below -0.5.
Interval densityRule(std::span<const Interval> a) {
    const Interval width = a.size() == 2 ? a[1] : Interval::point(Type::Float, {1, 0, 0});
    if (a[0].type != Type::Float || width.type != Type::Float || !(width.lo.x > 0.0))
        return floatInterval(0.0, 1.0); // every branch lands in [0, 1] (NaN aside)
    const Interval half = Interval::point(Type::Float, {0.5, 0, 0});
    const Interval ratio[] = {a[0], width};
    const Interval t[] = {half, div(ratio)};
    const Interval args[] = {sub(t), Interval::point(Type::Float, {0, 0, 0}), Interval::point(Type::Float, {1, 0, 0})};
    return clampRule(args);
}

Interval selectRule(std::span<const Interval> a) {
    if (a[0].type == Type::Bool && a[0].exact) return a[0].lo.x == 1.0 ? a[1] : a[2];
    Interval r{a[1].type, glm::min(a[1].lo, a[2].lo), glm::max(a[1].hi, a[2].hi), false};
    return r;
}

// Comparisons of numbers: surely true, surely false, or unknown.
template <bool Strict>
Interval lessThan(const Interval& a, const Interval& b) {
    if (a.type != b.type || a.type == Type::Bool || components(a.type) != 1) return boolInterval(true, true);
    const bool surelyTrue = Strict ? a.hi.x < b.lo.x : a.hi.x <= b.lo.x;
    const bool surelyFalse = Strict ? a.lo.x >= b.hi.x : a.lo.x > b.hi.x;
    return boolInterval(!surelyTrue, !surelyFalse);
}
Interval lt(std::span<const Interval> a) { return lessThan<true>(a[0], a[1]); }
Interval le(std::span<const Interval> a) { return lessThan<false>(a[0], a[1]); }
Interval gt(std::span<const Interval> a) { return lessThan<true>(a[1], a[0]); }
Interval ge(std::span<const Interval> a) { return lessThan<false>(a[1], a[0]); }

bool canBe(const Interval& b, bool value) { return value ? b.hi.x == 1.0 : b.lo.x == 0.0; }
Interval andRule(std::span<const Interval> a) {
    return boolInterval(canBe(a[0], false) || canBe(a[1], false), canBe(a[0], true) && canBe(a[1], true));
}
Interval orRule(std::span<const Interval> a) {
    return boolInterval(canBe(a[0], false) && canBe(a[1], false), canBe(a[0], true) || canBe(a[1], true));
}
Interval notRule(std::span<const Interval> a) { return boolInterval(canBe(a[0], true), canBe(a[0], false)); }

// == and != of floats, ints or bools: surely different when the intervals are disjoint, surely
// equal when both are the same exact value (-0 == 0 holds; a NaN constant equals nothing).
Interval equality(const Interval& a, const Interval& b, bool equal) {
    if (a.type != b.type || components(a.type) != 1) return boolInterval(true, true);
    const bool different = a.hi.x < b.lo.x || b.hi.x < a.lo.x;
    const bool same = a.exact && b.exact && a.lo.x == b.lo.x;
    return equal ? boolInterval(!same, !different) : boolInterval(!different, !same);
}

// The component-wise math builtins on vec2/vec3: the float rule per component, a float operand
// broadcast; exact where every component is.
template <Interval (*Scalar)(std::span<const Interval>)>
Interval componentwise(std::span<const Interval> a) {
    Type type = Type::Float;
    for (const Interval& x : a) {
        if (!isFloatLike(x.type)) return Interval::unknown(a[0].type);
        if (components(x.type) > components(type)) type = x.type;
    }
    if (type == Type::Float) return Scalar(a);
    Interval r{type, glm::dvec3(0.0), glm::dvec3(0.0), true};
    Interval scalars[3];
    for (int c = 0; c < components(type); ++c) {
        for (size_t i = 0; i < a.size(); ++i) scalars[i] = {Type::Float, {lo(a[i], c), 0, 0}, {hi(a[i], c), 0, 0}, a[i].exact};
        const Interval s = Scalar(std::span<const Interval>(scalars, a.size()));
        r.lo[c] = s.lo.x;
        r.hi[c] = s.hi.x;
        r.exact = r.exact && s.exact;
    }
    return r;
}

Interval eqRule(std::span<const Interval> a) { return equality(a[0], a[1], true); }
Interval neRule(std::span<const Interval> a) { return equality(a[0], a[1], false); }

// ---- Component-wise math (float rules; `componentwise` applies them to vec2/vec3) ----

// fract(x) = x - floor(x) lies in [0, 1] (1 for tiny negative x); inside one unit cell it is x
// minus that cell's floor, a subtraction rounded monotonically. Infinite x gives NaN.
Interval fractRule(std::span<const Interval> a) {
    const double l = a[0].lo.x, h = a[0].hi.x;
    if (!std::isfinite(l) || !std::isfinite(h)) return Interval::unknown(Type::Float);
    if (a[0].exact) {
        const float x = float(l);
        return Interval::point(Type::Float, {x - std::floor(x), 0, 0}); // the record's float operations
    }
    if (std::floor(l) != std::floor(h)) return floatInterval(0.0, 1.0);
    return floatInterval(std::max(0.0, down(l - std::floor(l))), std::min(1.0, up(h - std::floor(l))));
}

Interval sqrtRule(std::span<const Interval> a) {
    if (!(a[0].lo.x >= 0.0)) return Interval::unknown(Type::Float); // sqrt of a negative is NaN
    return widened(floatInterval(std::sqrt(a[0].lo.x), std::sqrt(a[0].hi.x)), kSqrtTolerance, 1e-5);
}

// sin(x + phase) over [l, h]: the end values, and +-1 where a crest or trough lies inside.
Interval sineRule(const Interval& x, bool cosine) {
    const double l = x.lo.x, h = x.hi.x, twoPi = 2.0 * std::numbers::pi;
    if (!std::isfinite(l) || !std::isfinite(h)) return Interval::unknown(Type::Float);
    auto f = [&](double v) { return cosine ? std::cos(v) : std::sin(v); };
    auto contains = [&](double crest) { return std::ceil((l - crest) / twoPi) * twoPi + crest <= h; };
    const double crest = cosine ? 0.0 : std::numbers::pi / 2; // where the value is 1; -1 half a turn on
    double lo = std::min(f(l), f(h)), hi = std::max(f(l), f(h));
    if (h - l >= twoPi || contains(crest)) hi = 1.0;
    if (h - l >= twoPi || contains(crest + std::numbers::pi)) lo = -1.0;
    return widened(floatInterval(lo, hi), kTrigTolerance + 1e-6, 0.0);
}
Interval sinRule(std::span<const Interval> a) { return sineRule(a[0], false); }
Interval cosRule(std::span<const Interval> a) { return sineRule(a[0], true); }

// x^y for x > 0 is monotone in x for a fixed sign of y and in y for a fixed side of 1
// (log x^y = y log x is bilinear in y and log x), so the box's corners bound it. Widened by the
// Vulkan bound for exp2(y log2 x): 3 + 2 |y log2 x| ulp, plus the record's tolerance.
Interval powRule(std::span<const Interval> a) {
    const Interval& x = a[0];
    const Interval& y = a[1];
    if (!(x.lo.x > 0.0) || !finite(x) || !finite(y)) return Interval::unknown(Type::Float);
    double l = kInf, h = -kInf, exponent = 0;
    for (double xc : {x.lo.x, x.hi.x})
        for (double yc : {y.lo.x, y.hi.x}) {
            l = std::min(l, std::pow(xc, yc));
            h = std::max(h, std::pow(xc, yc));
            exponent = std::max(exponent, std::fabs(yc * std::log2(xc)));
        }
    return widened(floatInterval(l, h), kPowTolerance, (4.0 + 2.0 * exponent) * 0x1p-23 + 1e-6);
}

// mix(x, y, a) = x * (1 - a) + y * a by interval arithmetic; for a in [0, 1] it also lies in the
// hull of x and y (up to the roundings). Exact operands give the record's float result.
Interval mixRule(std::span<const Interval> a) {
    if (a[0].exact && a[1].exact && a[2].exact) {
        const float x = float(a[0].lo.x), y = float(a[1].lo.x), t = float(a[2].lo.x);
        const float r = x * (1.0f - t) + y * t;
        if (std::isfinite(r)) return Interval::point(Type::Float, {r, 0, 0}); // else NaN may come: below
    }
    const Interval oneMinus[] = {Interval::point(Type::Float, {1, 0, 0}), a[2]};
    const Interval left[] = {a[0], sub(oneMinus)}, right[] = {a[1], a[2]};
    const Interval terms[] = {mul(left), mul(right)};
    Interval r = add(terms);
    if (a[2].lo.x >= 0.0 && a[2].hi.x <= 1.0 && finite(a[0]) && finite(a[1])) {
        const double scale = std::max({std::fabs(a[0].lo.x), std::fabs(a[0].hi.x), std::fabs(a[1].lo.x), std::fabs(a[1].hi.x)});
        const double slack = scale * 1e-6 + kTiny;
        r.lo.x = std::max(r.lo.x, std::min(a[0].lo.x, a[1].lo.x) - slack);
        r.hi.x = std::min(r.hi.x, std::max(a[0].hi.x, a[1].hi.x) + slack);
    }
    return r;
}

// smoothstep(e0, e1, x) = t * t * (3 - 2t), t = clamp((x - e0) / (e1 - e0), 0, 1): increasing in
// t; NaN only from 0 / 0. A t proven exactly 0 or 1 gives exactly 0 or 1 (the division's error is
// inside div's widening, so the GPU agrees).
Interval smoothstepRule(std::span<const Interval> a) {
    if (!finite(a[0]) || !finite(a[1]) || !finite(a[2])) return Interval::unknown(Type::Float);
    const Interval numeratorArgs[] = {a[2], a[0]}, denominatorArgs[] = {a[1], a[0]};
    const Interval quotientArgs[] = {sub(numeratorArgs), sub(denominatorArgs)};
    const Interval& n = quotientArgs[0];
    const Interval& d = quotientArgs[1];
    if (n.lo.x <= 0.0 && n.hi.x >= 0.0 && d.lo.x <= 0.0 && d.hi.x >= 0.0) return Interval::unknown(Type::Float);
    const Interval clampArgs[] = {div(quotientArgs), Interval::point(Type::Float, {0, 0, 0}),
                                  Interval::point(Type::Float, {1, 0, 0})};
    const Interval t = clampRule(clampArgs);
    if (t.exact) {
        const float v = float(t.lo.x);
        return Interval::point(Type::Float, {v * v * (3.0f - 2.0f * v), 0, 0});
    }
    auto cubic = [](double v) { return v * v * (3.0 - 2.0 * v); };
    return widened(floatInterval(cubic(std::max(t.lo.x, 0.0)), cubic(std::min(t.hi.x, 1.0))), 1e-6, 1e-6);
}

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
Interval simplexRule(std::span<const Interval> a) {
    return finitePoint(a[0]) ? symmetric(kSimplexBound + kNoiseSlack) : Interval::unknown(Type::Float);
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

// ---- Signed distances ----

// sdf_plane(p, n, offset) = dot(p, n) / |n| - offset; a zero normal gives -offset (exactly).
Interval planeRule(std::span<const Interval> a) {
    if (!vec3Args(a, {0, 1}) || a[2].type != Type::Float) return Interval::unknown(Type::Float);
    if (a[1].exact && a[1].lo == glm::dvec3(0.0)) return neg(a.subspan(2, 1));
    const Interval normal[] = {a[1]};
    const Interval length = lengthRule(normal);
    if (!(length.lo.x > 0.0)) return Interval::unknown(Type::Float); // may be the -offset branch
    const Interval dotArgs[] = {a[0], a[1]};
    const Interval quotient[] = {dotRule(dotArgs), length};
    const Interval difference[] = {div(quotient), a[2]};
    return widened(sub(difference), kPlaneTolerance, 1e-6);
}

// sdf_heightfield(p, height) = p.y - height, one rounding (bit-exact on the GPU).
Interval heightfieldRule(std::span<const Interval> a) {
    if (a[0].type != Type::Vec3 || a[1].type != Type::Float) return Interval::unknown(Type::Float);
    const Interval args[] = {{Type::Float, {a[0].lo.y, 0, 0}, {a[0].hi.y, 0, 0}, a[0].exact}, a[1]};
    return sub(args);
}

// Polynomial smooth minimum: k <= 0 is min(a, b) (exactly, also on the GPU); for k > 0 the
// result is mix(b, a, h) - k h (1 - h) with h in [0, 1], so in [min - k/4, min] (k h (1 - h) <=
// k/4), exactly min where |a - b| >= k (h is 0 or 1). The float h, blend and product each err by
// a few ulp of |a| + |b| + k. Finite operands only (inf / inf or inf * 0 is NaN).
Interval smoothUnionRule(std::span<const Interval> a) {
    const Interval& k = a[2];
    if (k.hi.x <= 0.0) return minRule(a.first(2));
    if (!finite(a[0]) || !finite(a[1]) || !finite(k)) return Interval::unknown(Type::Float);
    const Interval hard = minRule(a.first(2));
    const double kMax = std::max(k.hi.x, 0.0);
    const double scale = std::max({std::fabs(a[0].lo.x), std::fabs(a[0].hi.x), std::fabs(a[1].lo.x),
                                   std::fabs(a[1].hi.x)}) + kMax;
    const double apart = std::max(a[1].lo.x - a[0].hi.x, a[0].lo.x - a[1].hi.x);
    const double depth = apart >= kMax * (1 + 1e-5) + scale * 1e-6 ? 0.0 : kMax / 4;
    return widened(floatInterval(hard.lo.x - depth, hard.hi.x), kSmoothTolerance + scale * 1e-5, 0.0);
}
Interval negated(const Interval& x) { return {x.type, -x.hi, -x.lo, x.exact}; }
Interval smoothIntersectRule(std::span<const Interval> a) { // -smooth_union(-a, -b, k)
    const Interval args[] = {negated(a[0]), negated(a[1]), a[2]};
    return negated(smoothUnionRule(args));
}
Interval smoothSubtractRule(std::span<const Interval> a) { // smooth_intersect(a, -b, k)
    const Interval args[] = {a[0], negated(a[1]), a[2]};
    return smoothIntersectRule(args);
}

} // namespace

Interval Interval::unknown(Type type) { return {type, glm::dvec3(-kInf), glm::dvec3(kInf), false}; }

RangeRule rangeRule(std::string_view function) {
    static const std::unordered_map<std::string_view, RangeRule> rules = {
        {"add", add}, {"sub", sub}, {"mul", mul}, {"div", div}, {"neg", neg},
        {"min", componentwise<minRule>}, {"max", componentwise<maxRule>}, {"clamp", componentwise<clampRule>},
        {"abs", componentwise<absRule>}, {"floor", componentwise<floorRule>}, {"fract", componentwise<fractRule>},
        {"mix", componentwise<mixRule>}, {"smoothstep", componentwise<smoothstepRule>},
        {"sqrt", componentwise<sqrtRule>}, {"pow", componentwise<powRule>}, {"sin", componentwise<sinRule>},
        {"cos", componentwise<cosRule>},
        {"vec2", vecRule}, {"vec3", vecRule}, {"dot", dotRule}, {"length", lengthRule},
        {"lt", lt}, {"le", le}, {"gt", gt}, {"ge", ge}, {"eq", eqRule}, {"ne", neRule},
        {"and", andRule}, {"or", orRule}, {"not", notRule}, {"select", selectRule},
        {"perlin3", perlinRule}, {"simplex3", simplexRule}, {"value3", valueRule},
        {"worley3", worleyRule<3>}, {"worley_f1", worleyRule<0>}, {"worley_f2", worleyRule<1>},
        {"worley_f2f1", worleyRule<2>}, {"curl3", curlRule},
        {"fbm", fbmRule}, {"ridged", ridgedRule}, {"turbulence", turbulenceRule},
        {"warp", warpRule}, {"warped_fbm", warpedFbmRule},
        {"sdf_sphere", sphereRule}, {"sdf_box", boxRule}, {"sdf_capsule", capsuleRule},
        {"sdf_plane", planeRule}, {"sdf_heightfield", heightfieldRule},
        {"sdf_union", minRule}, {"sdf_intersect", maxRule}, {"sdf_subtract", subtractRule},
        {"sdf_smooth_union", smoothUnionRule}, {"sdf_smooth_subtract", smoothSubtractRule},
        {"sdf_smooth_intersect", smoothIntersectRule},
        {"density", densityRule},
    };
    const auto it = rules.find(function);
    return it == rules.end() ? nullptr : it->second;
}

} // namespace voxc
