// Range rules of the signed-distance builtins.
#include "IntervalMath.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace voxc::intervals {

namespace {

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

const NamedRule kSdfRules[] = {
    {"sdf_sphere", sphereRule}, {"sdf_box", boxRule}, {"sdf_capsule", capsuleRule},
    {"sdf_plane", planeRule}, {"sdf_heightfield", heightfieldRule},
    {"sdf_smooth_union", smoothUnionRule}, {"sdf_smooth_subtract", smoothSubtractRule},
    {"sdf_smooth_intersect", smoothIntersectRule},
};

} // namespace

std::span<const NamedRule> sdfRules() { return kSdfRules; }

} // namespace voxc::intervals
