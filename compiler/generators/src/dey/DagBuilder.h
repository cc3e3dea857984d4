#pragma once
// Small helpers the generators use to write field DAGs: typed constants, the position input,
// registry calls, the feature placement (translate/rotate) and swept spheres.
#include "voxc/generators/dey/Generators.h"
#include "voxc/program/FieldDag.h"

#include <glm/mat3x3.hpp>
#include <initializer_list>
#include <vector>

namespace voxc::dey {

class DagBuilder {
public:
    uint32_t number(double value);
    uint32_t vec3(glm::dvec3 value);
    uint32_t position(); // grid-local p = vec3(x, y, z)
    uint32_t component(uint32_t vector, uint32_t index);
    // A call of registry function `name`; the operand types must fit its type rule.
    uint32_t call(std::string_view name, std::initializer_list<uint32_t> operands);
    // The nodes `root` depends on, renumbered, as a field whose root is `root`.
    Field field(uint32_t root) const;

private:
    FieldDag dag_;
};

// `rotate` (degrees about x, then y, then z, around `pivot`) followed by `translate`.
struct Placement {
    glm::dmat3 rotation{1.0};
    glm::dvec3 pivot{0.0};
    glm::dvec3 translate{0.0};

    static Placement of(const GeneratorParams& params, glm::dvec3 pivot);
    bool identity() const;
    glm::dvec3 apply(glm::dvec3 point) const;
    // The feature's own coordinates of the grid position p (the inverse placement), as a vec3 node.
    uint32_t inverseOfPosition(DagBuilder& builder) const;
};

// Signed distance to the union of capsules between consecutive points; segment i has the mean
// of radii[i] and radii[i + 1]. Needs at least two points.
uint32_t sweptSpheres(DagBuilder& builder, const std::vector<glm::dvec3>& points, const std::vector<double>& radii);

} // namespace voxc::dey
