#include "voxc/builtins/Intervals.h"

#include "intervals/IntervalMath.h"

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

using namespace intervals;

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

} // namespace

Interval Interval::unknown(Type type) { return {type, glm::dvec3(-kInf), glm::dvec3(kInf), false}; }

RangeRule rangeRule(std::string_view function) {
    static const std::unordered_map<std::string_view, RangeRule> rules = [] {
        std::unordered_map<std::string_view, RangeRule> all = {
        {"add", add}, {"sub", sub}, {"mul", mul}, {"div", div}, {"neg", neg},
        {"min", componentwise<minRule>}, {"max", componentwise<maxRule>}, {"clamp", componentwise<clampRule>},
        {"abs", componentwise<absRule>}, {"floor", componentwise<floorRule>}, {"fract", componentwise<fractRule>},
        {"mix", componentwise<mixRule>}, {"smoothstep", componentwise<smoothstepRule>},
        {"sqrt", componentwise<sqrtRule>}, {"pow", componentwise<powRule>}, {"sin", componentwise<sinRule>},
        {"cos", componentwise<cosRule>},
        {"vec2", vecRule}, {"vec3", vecRule}, {"dot", dotRule}, {"length", lengthRule},
        {"lt", lt}, {"le", le}, {"gt", gt}, {"ge", ge}, {"eq", eqRule}, {"ne", neRule},
        {"and", andRule}, {"or", orRule}, {"not", notRule}, {"select", selectRule},
        {"sdf_union", minRule}, {"sdf_intersect", maxRule}, {"sdf_subtract", subtractRule},
        {"density", densityRule},
        };
        for (auto table : {intervals::noiseRules(), intervals::sdfRules()})
            for (const intervals::NamedRule& named : table) all.emplace(named.function, named.rule);
        return all;
    }();
    const auto it = rules.find(function);
    return it == rules.end() ? nullptr : it->second;
}

} // namespace voxc
