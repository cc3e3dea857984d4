#include "Placement.h"

#include "voxc/core/Errors.h"

#include <cmath>
#include <numbers>

namespace voxc::dey {

Placement Placement::of(const GeneratorParams& params, glm::dvec3 pivot) {
    const glm::dvec3 angles = params.vec("rotate") * (std::numbers::pi / 180.0);
    const double cx = std::cos(angles.x), sx = std::sin(angles.x);
    const double cy = std::cos(angles.y), sy = std::sin(angles.y);
    const double cz = std::cos(angles.z), sz = std::sin(angles.z);
    // glm matrices are column-major: m[column][row].
    const glm::dmat3 rx(1, 0, 0, 0, cx, sx, 0, -sx, cx);
    const glm::dmat3 ry(cy, 0, -sy, 0, 1, 0, sy, 0, cy);
    const glm::dmat3 rz(cz, sz, 0, -sz, cz, 0, 0, 0, 1);
    Placement placement;
    placement.rotation = rz * ry * rx;
    placement.pivot = pivot;
    placement.translate = params.vec("translate");
    return placement;
}

bool Placement::identity() const { return rotation == glm::dmat3(1.0) && translate == glm::dvec3(0.0); }

glm::dvec3 Placement::apply(glm::dvec3 point) const { return rotation * (point - pivot) + pivot + translate; }

uint32_t Placement::inverseOfPosition(FieldBuilder& builder) const {
    const uint32_t p = builder.position();
    if (identity()) return p;
    // q = R^T (p - pivot - translate) + pivot, one component at a time with plain mul/add.
    const glm::dvec3 shift = pivot + translate;
    uint32_t local[3];
    for (uint32_t j = 0; j < 3; ++j)
        local[j] = builder.call("sub", {builder.component(p, j), builder.number(shift[j])});
    uint32_t q[3];
    for (uint32_t i = 0; i < 3; ++i) {
        // Row i of R^T is column i of R.
        uint32_t sum = builder.call("mul", {local[0], builder.number(rotation[i][0])});
        for (uint32_t j = 1; j < 3; ++j)
            sum = builder.call("add", {sum, builder.call("mul", {local[j], builder.number(rotation[i][j])})});
        q[i] = builder.call("add", {sum, builder.number(pivot[i])});
    }
    return builder.call("vec3", {q[0], q[1], q[2]});
}

uint32_t sweptSpheres(FieldBuilder& builder, const std::vector<glm::dvec3>& points, const std::vector<double>& radii) {
    VOXC_ASSERT(points.size() >= 2 && radii.size() == points.size());
    const uint32_t p = builder.position();
    uint32_t distance = 0;
    for (size_t i = 0; i + 1 < points.size(); ++i) {
        const double radius = 0.5 * (radii[i] + radii[i + 1]);
        const uint32_t capsule = builder.call(
            "sdf_capsule", {p, builder.vec3(points[i]), builder.vec3(points[i + 1]), builder.number(radius)});
        distance = i == 0 ? capsule : builder.call("sdf_union", {distance, capsule});
    }
    return distance;
}

} // namespace voxc::dey
