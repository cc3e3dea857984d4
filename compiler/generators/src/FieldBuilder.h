#pragma once
// How the generators write field DAGs: typed constants, the position inputs, registry calls
// checked against their type rules, and the field of a root.
#include "voxc/program/FieldDag.h"

#include <glm/vec3.hpp>
#include <initializer_list>
#include <string_view>

namespace voxc::generators {

class FieldBuilder {
public:
    uint32_t number(double value); // a float constant
    uint32_t vec3(glm::dvec3 value);
    uint32_t seed(uint32_t value); // an int constant (a noise seed's bit pattern)
    uint32_t position();      // grid-local p = vec3(x, y, z)
    uint32_t worldPosition(); // vec3(wx, wy, wz)
    uint32_t component(uint32_t vector, uint32_t index);
    // A call of registry function `name`; the operand types must fit its type rule.
    uint32_t call(std::string_view name, std::initializer_list<uint32_t> operands);
    // Any other node, as given.
    uint32_t add(const FieldNode& node);
    // The nodes `root` depends on, renumbered, as a field whose root is `root`.
    Field field(uint32_t root) const;

private:
    uint32_t inputs(FieldInput x); // vec3 of the inputs x, x + 1, x + 2
    FieldDag dag_;
};

} // namespace voxc::generators
