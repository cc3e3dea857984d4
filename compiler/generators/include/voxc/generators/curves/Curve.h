#pragma once
// Feature curves (Becher et al. section 3.1, spec A3.2): a clamped uniform cubic B-spline with
// constraint points, sampled in double precision at plan time into spine samples with
// interpolated bitangents (rotation-minimising transport), noise parameters and material, then
// into ribbon triangles for voxelisation.
#include "voxc/generators/curves/Limits.h"

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace voxc::curves {

struct ConstraintPoint {
    double t = 0.0;                     // on [0, 1]; 0 and 1 required, strictly increasing
    std::optional<glm::dvec3> left;     // b_l, voxels; default 3 * normalize(up x T)
    std::optional<glm::dvec3> right;    // b_r, voxels; default 3 * normalize(T x up)
    double amplitude = 0.0;             // alpha, voxels, [0, 16]
    double roughness = 0.5;             // beta, [0, 1]
    uint16_t material = 0;              // 0 = none
};

struct FeatureCurve {
    std::vector<glm::dvec3> points;     // >= 4 control vertices
    std::vector<ConstraintPoint> constraints;
    bool seed = true;                   // false: a guidance curve (steers normals only)
};

// One spine sample: position, unit tangent, both bitangents (perpendicular to the tangent) and
// the interpolated constraint attributes.
struct SpineSample {
    double t = 0.0;
    glm::dvec3 position{0.0}, tangent{0.0}, left{0.0}, right{0.0};
    double amplitude = 0.0, roughness = 0.0;
    uint16_t material = 0;
};

struct RibbonVertex {
    glm::dvec3 position{0.0}, normal{0.0};
    double amplitude = 0.0, roughness = 0.0;
};

struct RibbonTriangle {
    RibbonVertex v[3];
    uint16_t material = 0;
    bool seed = true;
};

// Clamped uniform cubic B-spline (knots 0,0,0,0, 1/(n-2), ..., (n-3)/(n-2), 1,1,1,1 for n+1
// control vertices) and its derivative with respect to t, t in [0, 1]. The knots and the
// derivative's control points are built once, so sampling a curve of n vertices at m values of
// t costs O(n + m log n).
class ClampedSpline {
public:
    explicit ClampedSpline(const std::vector<glm::dvec3>& points); // at least 4 points
    glm::dvec3 point(double t) const;
    glm::dvec3 derivative(double t) const;

private:
    std::vector<glm::dvec3> points_;
    std::vector<double> knots_;
    std::vector<glm::dvec3> derivativePoints_;
    std::vector<double> derivativeKnots_;
};

// One evaluation of a spline built for it (tests; sampleCurve builds the spline once).
glm::dvec3 splinePoint(const std::vector<glm::dvec3>& points, double t);
glm::dvec3 splineDerivative(const std::vector<glm::dvec3>& points, double t);

// The checks of sampleCurve: counts, finite values within Limits::maxCoordinate, t order, ranges.
void validateCurve(const FeatureCurve& curve, const Limits& limits, const std::string& name);

// Validates `curve` (ParameterError, LimitError; `name` prefixes parameter names) and samples it:
// 8 * (n + 1) uniform segments doubled until every chord <= 0.5 voxel, plus every constraint t.
std::vector<SpineSample> sampleCurve(const FeatureCurve& curve, const Limits& limits, const std::string& name);

// Two triangles per segment and ribbon, in order: per segment, right ribbon then left ribbon.
// Normals: right ribbon normalize(b_r x T), left ribbon normalize(T x b_l) (flat default: +y).
std::vector<RibbonTriangle> ribbonTriangles(const std::vector<SpineSample>& samples, bool seed);

} // namespace voxc::curves
