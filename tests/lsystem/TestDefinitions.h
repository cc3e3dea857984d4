#pragma once
// Definitions with the spec's §10 test parameters: axiom Z, start (0,0,0), yaw 0 = +x, angle 45, step 1.
#include "voxc/generators/lsystem/Definition.h"

#include <gtest/gtest.h>
#include <glm/vec3.hpp>

namespace voxc::lsystem::test {

inline Definition thesisDefinition(std::string axiom = "Z") {
    Definition d;
    d.axiom = std::move(axiom);
    d.expansions = 0;
    d.params.angle = 45;
    d.params.step = 1;
    return d;
}

// One deterministic production Z -> rhs.
inline Definition withProduction(const std::string& rhs, uint32_t expansions) {
    Definition d = thesisDefinition();
    d.productions['Z'] = {{rhs, SymbolType::None, 1.0}};
    d.expansions = expansions;
    return d;
}

inline void expectNear(glm::dvec3 actual, glm::dvec3 expected, double tolerance = 1e-6) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << "x";
    EXPECT_NEAR(actual.y, expected.y, tolerance) << "y";
    EXPECT_NEAR(actual.z, expected.z, tolerance) << "z";
}

} // namespace voxc::lsystem::test
