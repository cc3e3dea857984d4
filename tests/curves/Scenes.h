#pragma once
// Curves and constraint grids the curve tests share.
#include "voxc/generators/curves/Curves.h"

#include <glm/geometric.hpp>

namespace voxc::curves::test {

// A straight seed curve through q along `tangent`, ribbons of half-width `width` spanning the
// plane with normal n (right = width * (T x n), so the ribbon normal is n).
inline FeatureCurve planeCurve(const glm::dvec3& q, const glm::dvec3& n, const glm::dvec3& tangent, double width,
                               uint16_t material = 0) {
    FeatureCurve c;
    for (double s : {-60.0, -20.0, 20.0, 60.0}) c.points.push_back(q + s * tangent);
    const glm::dvec3 right = width * glm::cross(tangent, n);
    for (double t : {0.0, 1.0}) {
        ConstraintPoint p;
        p.t = t;
        p.right = right;
        p.left = -right;
        p.material = material;
        c.constraints.push_back(p);
    }
    return c;
}

// A cliff-like curved seed curve with varying amplitude and roughness, and a guidance curve.
inline std::vector<FeatureCurve> cliffScene() {
    FeatureCurve cliff;
    cliff.points = {{4.0, 12.0, 10.0}, {20.0, 14.0, 24.0}, {36.0, 18.0, 30.0}, {50.0, 16.0, 44.0}, {60.0, 13.0, 56.0}};
    ConstraintPoint a, b, c;
    a.t = 0.0, a.amplitude = 2.0, a.roughness = 0.2, a.material = 1;
    b.t = 0.4, b.amplitude = 6.0, b.roughness = 0.8, b.material = 2;
    b.right = glm::dvec3(0.0, 3.0, 2.0);
    c.t = 1.0, c.amplitude = 1.0, c.roughness = 0.5, c.material = 3;
    cliff.constraints = {a, b, c};
    FeatureCurve guide;
    guide.seed = false;
    guide.points = {{8.0, 26.0, 50.0}, {24.0, 27.0, 52.0}, {40.0, 26.0, 50.0}, {56.0, 25.0, 52.0}};
    ConstraintPoint g0, g1;
    g0.t = 0.0, g0.material = 4, g0.amplitude = 3.0;
    g1.t = 1.0, g1.material = 4, g1.amplitude = 3.0;
    guide.constraints = {g0, g1};
    return {cliff, guide};
}

inline Box box643() { return Box{glm::ivec3(0), glm::ivec3(64, 32, 64)}; }

} // namespace voxc::curves::test
