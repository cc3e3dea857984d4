#include "voxc/builtins/Intervals.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

namespace voxc {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// One float rounding is at most 2^-24 relative; 1e-6 also covers the double arithmetic of the
// bounds. kTiny covers results that round to or from subnormals.
constexpr double kRelative = 1e-6, kTiny = 1e-36;

int components(Type t) { return t == Type::Vec3 ? 3 : t == Type::Vec2 ? 2 : 1; }
bool isFloatLike(Type t) { return t == Type::Float || t == Type::Vec2 || t == Type::Vec3; }

double down(double x) { return std::isnan(x) ? -kInf : x - std::fabs(x) * kRelative - kTiny; }
double up(double x) { return std::isnan(x) ? kInf : x + std::fabs(x) * kRelative + kTiny; }

// Component c of an operand, a float broadcast to every component.
double lo(const Interval& a, int c) { return a.type == Type::Float ? a.lo.x : a.lo[c]; }
double hi(const Interval& a, int c) { return a.type == Type::Float ? a.hi.x : a.hi[c]; }

Interval floatInterval(double l, double h) { return {Type::Float, {l, 0, 0}, {h, 0, 0}, false}; }
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
// ordered the result is one operand (exactly); otherwise the hull.
Interval pick(const Interval& a, const Interval& b, bool maximum) {
    if (a.type != Type::Float || b.type != Type::Float) return Interval::unknown(Type::Float);
    if (a.hi.x < b.lo.x) return maximum ? b : a;
    if (b.hi.x < a.lo.x) return maximum ? a : b;
    return floatInterval(std::min(a.lo.x, b.lo.x), std::max(a.hi.x, b.hi.x));
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
// Each float step of a sum of n products rounds once; widen by n + 1 roundings.
double downBy(double x, int steps) { for (int i = 0; i < steps; ++i) x = down(x); return x; }
double upBy(double x, int steps) { for (int i = 0; i < steps; ++i) x = up(x); return x; }

Interval dotRule(std::span<const Interval> a) {
    if (!isFloatLike(a[0].type) || a[0].type == Type::Float || a[0].type != a[1].type)
        return Interval::unknown(Type::Float);
    auto [l, h] = dotBounds(a[0], a[1]);
    return floatInterval(downBy(l, 6), upBy(h, 6));
}
Interval lengthRule(std::span<const Interval> a) {
    if (a[0].type == Type::Float || !isFloatLike(a[0].type)) return Interval::unknown(Type::Float);
    double l = 0, h = 0;
    for (int c = 0; c < components(a[0].type); ++c) {
        l += squaredGap(a[0].lo[c], a[0].hi[c]);
        h += std::max(a[0].lo[c] * a[0].lo[c], a[0].hi[c] * a[0].hi[c]);
    }
    return floatInterval(std::max(0.0, downBy(std::sqrt(l), 8)), upBy(std::sqrt(h), 8));
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
    const double l = boxGap(a[0], a[1].lo, a[1].hi) - a[2].hi.x - m;
    double h = kInf;
    if (a[1].exact && a[2].exact)
        h = cornerMax(a[0], [&](glm::dvec3 p) { return glm::length(p - a[1].lo); }) - a[2].lo.x + m;
    return floatInterval(l, h);
}

Interval capsuleRule(std::span<const Interval> a) {
    if (!vec3Args(a, {0, 1, 2}) || a[3].type != Type::Float) return Interval::unknown(Type::Float);
    const double m = margin({&a[0], &a[1], &a[2], &a[3]});
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

// Noise: documented ranges with head room (Perlin and simplex about 1.04 at most).
Interval gradientNoise(std::span<const Interval>) { return floatInterval(-2.0, 2.0); }
Interval valueNoise(std::span<const Interval>) { return floatInterval(-1.0, 1.0); }
// fbm(p, octaves, lacunarity, gain, seed): at most 2 sum |gain|^k over the octaves.
Interval fbmRule(std::span<const Interval> a) {
    if (!a[1].exact || !a[3].exact) return Interval::unknown(Type::Float);
    const int octaves = std::clamp(int(a[1].lo.x), 1, 16);
    double sum = 0, amplitude = 1;
    for (int k = 0; k < octaves; ++k, amplitude *= std::fabs(a[3].lo.x)) sum += amplitude;
    return floatInterval(-2.0 * sum, 2.0 * sum);
}

} // namespace

Interval Interval::unknown(Type type) { return {type, glm::dvec3(-kInf), glm::dvec3(kInf), false}; }

RangeRule rangeRule(std::string_view function) {
    static const std::unordered_map<std::string_view, RangeRule> rules = {
        {"add", add}, {"sub", sub}, {"mul", mul}, {"div", div}, {"neg", neg},
        {"min", minRule}, {"max", maxRule}, {"clamp", clampRule}, {"abs", absRule}, {"floor", floorRule},
        {"vec2", vecRule}, {"vec3", vecRule}, {"dot", dotRule}, {"length", lengthRule},
        {"lt", lt}, {"le", le}, {"gt", gt}, {"ge", ge}, {"and", andRule}, {"or", orRule}, {"not", notRule},
        {"select", selectRule},
        {"sdf_sphere", sphereRule}, {"sdf_box", boxRule}, {"sdf_capsule", capsuleRule},
        {"sdf_union", minRule}, {"sdf_intersect", maxRule}, {"sdf_subtract", subtractRule},
        {"density", densityRule},
        {"perlin3", gradientNoise}, {"simplex3", gradientNoise}, {"value3", valueNoise}, {"fbm", fbmRule},
    };
    const auto it = rules.find(function);
    return it == rules.end() ? nullptr : it->second;
}

} // namespace voxc
