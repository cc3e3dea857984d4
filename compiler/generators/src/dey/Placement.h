#pragma once
// Helpers of Dey's generators: the feature placement (translate/rotate) and swept spheres, over
// the generators' DAG writer.
#include "voxc/generators/dey/Generators.h"
#include "../FieldBuilder.h"

#include <glm/mat3x3.hpp>
#include <initializer_list>
#include <vector>

namespace voxc::dey {

using generators::FieldBuilder;

// `rotate` (degrees about x, then y, then z, around `pivot`) followed by `translate`.
struct Placement {
    glm::dmat3 rotation{1.0};
    glm::dvec3 pivot{0.0};
    glm::dvec3 translate{0.0};

    static Placement of(const GeneratorParams& params, glm::dvec3 pivot);
    bool identity() const;
    glm::dvec3 apply(glm::dvec3 point) const;
    // The feature's own coordinates of the grid position p (the inverse placement), as a vec3 node.
    uint32_t inverseOfPosition(FieldBuilder& builder) const;
};

// Signed distance to the union of capsules between consecutive points; segment i has the mean
// of radii[i] and radii[i + 1]. Needs at least two points.
uint32_t sweptSpheres(FieldBuilder& builder, const std::vector<glm::dvec3>& points, const std::vector<double>& radii);

} // namespace voxc::dey
