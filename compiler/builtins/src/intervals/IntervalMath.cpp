#include "IntervalMath.h"

#include <algorithm>
#include <cmath>

namespace voxc::intervals {

namespace {

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

} // namespace

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

// min(a, b) = b < a ? b : a and max(a, b) = a < b ? b : a: when the operands are strictly
// ordered the result is one operand (exactly); otherwise min/max of the ends bound it. A NaN
// operand is ignored (minNum), and only an unknown operand, unbounded both ways, may be NaN,
// so the other operand's bound still holds.
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

} // namespace voxc::intervals
