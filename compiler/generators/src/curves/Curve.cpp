#include "voxc/generators/curves/Curve.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace voxc::curves {

ConvergenceError::ConvergenceError(std::string solve_, int32_t cycles_, double residual_, double tolerance_)
    : UserError(fmt::format("curves: the {} solve left a residual of {} after {} V-cycles (tolerance {})", solve_,
                            residual_, cycles_, tolerance_)),
      solve(std::move(solve_)), cycles(cycles_), residual(residual_), tolerance(tolerance_) {}

namespace {

constexpr int kDegree = 3;
const glm::dvec3 kUp{0.0, 1.0, 0.0};

std::vector<double> clampedKnots(size_t controlCount) {
    const size_t n = controlCount - 1;
    std::vector<double> knots(controlCount + kDegree + 1, 1.0);
    for (size_t i = 0; i <= kDegree; ++i) knots[i] = 0.0;
    for (size_t j = 1; j + 2 < n; ++j) knots[kDegree + j] = double(j) / double(n - 2);
    return knots;
}

// de Boor's evaluation of a B-spline of `degree` with `knots` (size ctrl.size() + degree + 1).
// The span is found by binary search: the knots do not depend on t, so they are built once per
// curve (ClampedSpline) and an evaluation costs O(log n + degree^2), not O(n).
glm::dvec3 deBoor(const std::vector<glm::dvec3>& ctrl, const std::vector<double>& knots, int degree, double t) {
    const int last = int(ctrl.size()) - 1;
    // The first span in [degree, last] whose next knot lies beyond t (the last span at t = 1).
    const int beyond = int(std::upper_bound(knots.begin(), knots.end(), t) - knots.begin());
    const int span = std::clamp(beyond - 1, degree, last);
    std::array<glm::dvec3, kDegree + 1> d;
    for (int j = 0; j <= degree; ++j) d[size_t(j)] = ctrl[size_t(j + span - degree)];
    for (int r = 1; r <= degree; ++r)
        for (int j = degree; j >= r; --j) {
            const double lo = knots[size_t(j + span - degree)];
            const double hi = knots[size_t(j + 1 + span - r)];
            const double a = hi > lo ? (t - lo) / (hi - lo) : 0.0;
            d[size_t(j)] = (1.0 - a) * d[size_t(j) - 1] + a * d[size_t(j)];
        }
    return d[size_t(degree)];
}

void checkVector(const glm::dvec3& v, const std::string& name, const Limits& limits) {
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(v[a]) || std::abs(v[a]) > limits.maxCoordinate)
            throw ParameterError(fmt::format("{}[{}]", name, a), v[a],
                                 fmt::format("must be finite with magnitude <= {}", limits.maxCoordinate));
}

void checkRange(double v, double lo, double hi, const std::string& name) {
    if (!(v >= lo && v <= hi)) throw ParameterError(name, v, fmt::format("must lie in [{}, {}]", lo, hi));
}

// One double-reflection step of the rotation-minimising frame (Wang et al. 2008): carries the
// vector r, perpendicular to tangent t0 at x0, to x1 with tangent t1.
glm::dvec3 transport(const glm::dvec3& x0, const glm::dvec3& t0, const glm::dvec3& x1, const glm::dvec3& t1,
                     glm::dvec3 r) {
    glm::dvec3 t = t0;
    const glm::dvec3 v1 = x1 - x0;
    const double c1 = glm::dot(v1, v1);
    if (c1 > 0.0) {
        r -= (2.0 / c1) * glm::dot(v1, r) * v1;
        t -= (2.0 / c1) * glm::dot(v1, t) * v1;
    }
    const glm::dvec3 v2 = t1 - t;
    const double c2 = glm::dot(v2, v2);
    if (c2 > 0.0) r -= (2.0 / c2) * glm::dot(v2, r) * v2;
    return r;
}

// The constraint's bitangent with the tangent component removed, or the default.
glm::dvec3 constraintBitangent(const std::optional<glm::dvec3>& given, const glm::dvec3& tangent, bool left,
                               const std::string& name) {
    if (!given) {
        const glm::dvec3 side = left ? glm::cross(kUp, tangent) : glm::cross(tangent, kUp);
        const double length = glm::length(side);
        if (length < 1e-9)
            throw ParameterError(name + " (default)", length,
                                 "the curve is vertical here, so the flat default is undefined: give the bitangents explicitly");
        return (3.0 / length) * side;
    }
    const glm::dvec3 projected = *given - glm::dot(*given, tangent) * tangent;
    const double length = glm::length(projected);
    if (length < 0.5) throw ParameterError(name, length, "length perpendicular to the curve must be >= 0.5 voxel");
    return projected;
}

} // namespace

ClampedSpline::ClampedSpline(const std::vector<glm::dvec3>& points)
    : points_(points), knots_(clampedKnots(points.size())), derivativePoints_(points.size() - 1),
      derivativeKnots_(knots_.begin() + 1, knots_.end() - 1) {
    for (size_t i = 0; i < derivativePoints_.size(); ++i)
        derivativePoints_[i] = (double(kDegree) / (knots_[i + kDegree + 1] - knots_[i + 1])) * (points[i + 1] - points[i]);
}

glm::dvec3 ClampedSpline::point(double t) const { return deBoor(points_, knots_, kDegree, std::clamp(t, 0.0, 1.0)); }

glm::dvec3 ClampedSpline::derivative(double t) const {
    return deBoor(derivativePoints_, derivativeKnots_, kDegree - 1, std::clamp(t, 0.0, 1.0));
}

glm::dvec3 splinePoint(const std::vector<glm::dvec3>& points, double t) { return ClampedSpline(points).point(t); }

glm::dvec3 splineDerivative(const std::vector<glm::dvec3>& points, double t) {
    return ClampedSpline(points).derivative(t);
}

void validateCurve(const FeatureCurve& curve, const Limits& limits, const std::string& name) {
    if (curve.points.size() < 4 || curve.points.size() > limits.maxControlPoints)
        throw ParameterError(name + " control vertex count", double(curve.points.size()),
                             fmt::format("must lie in [4, {}]", limits.maxControlPoints));
    for (size_t i = 0; i < curve.points.size(); ++i)
        checkVector(curve.points[i], fmt::format("{} point {}", name, i), limits);
    const auto& cps = curve.constraints;
    if (cps.size() < 2 || cps.size() > limits.maxConstraintPoints)
        throw ParameterError(name + " constraint point count", double(cps.size()),
                             fmt::format("must lie in [2, {}]", limits.maxConstraintPoints));
    for (size_t i = 0; i < cps.size(); ++i) {
        const std::string cp = fmt::format("{} constraint {}", name, i);
        if (!std::isfinite(cps[i].t)) throw ParameterError(cp + " t", cps[i].t, "must be finite");
        if (i == 0 && cps[i].t != 0.0) throw ParameterError(cp + " t", cps[i].t, "the first constraint must be at t = 0");
        if (i + 1 == cps.size() && cps[i].t != 1.0)
            throw ParameterError(cp + " t", cps[i].t, "the last constraint must be at t = 1");
        if (i > 0 && !(cps[i].t > cps[i - 1].t))
            throw ParameterError(cp + " t", cps[i].t, fmt::format("must be greater than the previous t = {}", cps[i - 1].t));
        checkRange(cps[i].amplitude, 0.0, 16.0, cp + " amplitude");
        checkRange(cps[i].roughness, 0.0, 1.0, cp + " roughness");
        if (cps[i].left) checkVector(*cps[i].left, cp + " left", limits);
        if (cps[i].right) checkVector(*cps[i].right, cp + " right", limits);
    }

}

std::vector<SpineSample> sampleCurve(const FeatureCurve& curve, const Limits& limits, const std::string& name) {
    validateCurve(curve, limits, name);
    const ClampedSpline spline(curve.points);
    const auto& cps = curve.constraints;
    // Chord refinement: positions are recomputed per doubling; the limit bounds the last one.
    uint64_t segments = 8 * uint64_t(curve.points.size());
    for (;;) {
        if (segments > limits.maxSegmentsPerCurve)
            throw LimitError(name + " segments (chords <= 0.5 voxel)", segments, limits.maxSegmentsPerCurve);
        double longest = 0.0;
        glm::dvec3 previous = spline.point(0.0);
        for (uint64_t i = 1; i <= segments; ++i) {
            const glm::dvec3 p = spline.point(double(i) / double(segments));
            longest = std::max(longest, glm::length(p - previous));
            previous = p;
        }
        if (longest <= 0.5) break;
        segments *= 2;
    }
    std::vector<double> ts;
    for (uint64_t i = 0; i <= segments; ++i) ts.push_back(double(i) / double(segments));
    for (const ConstraintPoint& c : cps) ts.push_back(c.t);
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());

    std::vector<SpineSample> samples(ts.size());
    for (size_t i = 0; i < ts.size(); ++i) {
        SpineSample& s = samples[i];
        s.t = ts[i];
        s.position = spline.point(s.t);
        const glm::dvec3 d = spline.derivative(s.t);
        const double speed = glm::length(d);
        if (speed < 1e-9) throw ParameterError(name + " tangent length at t", s.t, "coinciding control vertices leave no tangent");
        s.tangent = d / speed;
    }

    size_t a = 0; // sample index of constraint point c
    for (size_t c = 0; c + 1 < cps.size(); ++c) {
        const ConstraintPoint& ca = cps[c];
        const ConstraintPoint& cb = cps[c + 1];
        size_t b = a;
        while (ts[b] != cb.t) ++b;
        const std::string na = fmt::format("{} constraint {}", name, c), nb = fmt::format("{} constraint {}", name, c + 1);
        for (int side = 0; side < 2; ++side) {
            const bool left = side == 0;
            const glm::dvec3 ba = constraintBitangent(left ? ca.left : ca.right, samples[a].tangent, left, na + (left ? " left" : " right"));
            const glm::dvec3 bb = constraintBitangent(left ? cb.left : cb.right, samples[b].tangent, left, nb + (left ? " left" : " right"));
            std::vector<glm::dvec3> forward(b - a + 1), backward(b - a + 1);
            forward.front() = ba;
            for (size_t i = a; i < b; ++i)
                forward[i + 1 - a] = transport(samples[i].position, samples[i].tangent, samples[i + 1].position,
                                               samples[i + 1].tangent, forward[i - a]);
            backward.back() = bb;
            for (size_t i = b; i > a; --i)
                backward[i - 1 - a] = transport(samples[i].position, samples[i].tangent, samples[i - 1].position,
                                                samples[i - 1].tangent, backward[i - a]);
            for (size_t i = a; i <= b; ++i) {
                const double w = (ts[i] - ca.t) / (cb.t - ca.t);
                const glm::dvec3& tangent = samples[i].tangent;
                glm::dvec3 blend = (1.0 - w) * forward[i - a] + w * backward[i - a];
                blend -= glm::dot(blend, tangent) * tangent;
                const double length = glm::length(blend);
                if (length < 1e-9)
                    throw ParameterError(na + (left ? " left" : " right") + " blend at t", ts[i],
                                         "the bitangents of two constraint points cancel (opposite directions)");
                (left ? samples[i].left : samples[i].right) =
                    (((1.0 - w) * glm::length(ba) + w * glm::length(bb)) / length) * blend;
                samples[i].amplitude = (1.0 - w) * ca.amplitude + w * cb.amplitude;
                samples[i].roughness = (1.0 - w) * ca.roughness + w * cb.roughness;
                samples[i].material = (ts[i] - ca.t) <= (cb.t - ts[i]) ? ca.material : cb.material;
            }
        }
        a = b;
    }
    return samples;
}

std::vector<RibbonTriangle> ribbonTriangles(const std::vector<SpineSample>& samples, bool seed) {
    std::vector<RibbonTriangle> triangles;
    triangles.reserve(samples.size() * 4);
    auto vertex = [](const SpineSample& s, const glm::dvec3& offset, const glm::dvec3& normal) {
        return RibbonVertex{s.position + offset, normal, s.amplitude, s.roughness};
    };
    for (size_t i = 0; i + 1 < samples.size(); ++i) {
        const SpineSample& s0 = samples[i];
        const SpineSample& s1 = samples[i + 1];
        for (int side = 0; side < 2; ++side) {
            const bool left = side == 1;
            const glm::dvec3 b0 = left ? s0.left : s0.right, b1 = left ? s1.left : s1.right;
            const glm::dvec3 n0 = glm::normalize(left ? glm::cross(s0.tangent, b0) : glm::cross(b0, s0.tangent));
            const glm::dvec3 n1 = glm::normalize(left ? glm::cross(s1.tangent, b1) : glm::cross(b1, s1.tangent));
            const RibbonVertex c0 = vertex(s0, glm::dvec3(0.0), n0), c1 = vertex(s1, glm::dvec3(0.0), n1);
            const RibbonVertex e0 = vertex(s0, b0, n0), e1 = vertex(s1, b1, n1);
            triangles.push_back(RibbonTriangle{{c0, c1, e1}, s0.material, seed});
            triangles.push_back(RibbonTriangle{{c0, e1, e0}, s0.material, seed});
        }
    }
    return triangles;
}

} // namespace voxc::curves
