#pragma once
// Aggregate tests of a rule (Dey §5.3.2, "Abstract Voxel Grammars"): a `where` block tests the
// whole window, or a box of it, at once: its mean, min or max density, the share of solid cells
// (density >= 0.5) or the share of cells of one material, each against an inclusive range. A
// rule matches when its symbol's cells pass and every aggregate test passes. The interpreter
// (aggregatePasses below) and the sweep kernels (codegen/SweepKernel.cpp) evaluate them in the
// same order with the same float operations, so the two agree bit for bit.
#include <cstdint>
#include <glm/vec3.hpp>

namespace voxc {

enum class AggregateKind : uint8_t { Mean, Min, Max, SolidFraction, MaterialFraction };

// Densities at or above this are solid: for solid_fraction, and for material writes (Semantics.h).
constexpr float kSolidDensity = 0.5f;

struct AggregateTest {
    AggregateKind kind = AggregateKind::Mean;
    glm::ivec3 boxMin{0, 0, 0}; // window cells, half-open
    glm::ivec3 boxMax{0, 0, 0};
    uint8_t material = 0;       // MaterialFraction's material id
    // Mean: bounds of the sum of the box's densities (low * n and high * n, rounded to float), so
    // no division is needed; Min, Max: bounds of the value.
    float low = 0.0f;
    float high = 0.0f;
    // SolidFraction, MaterialFraction: bounds of the count of cells (ceil(low * n), floor(high * n)).
    uint32_t minCount = 0;
    uint32_t maxCount = 0;
};

// Visits the box's cells in cell order (x fastest, then y, then z), as both paths do.
template <typename Visit>
void forEachAggregateCell(const AggregateTest& test, Visit&& visit) {
    for (int z = test.boxMin.z; z < test.boxMax.z; ++z)
        for (int y = test.boxMin.y; y < test.boxMax.y; ++y)
            for (int x = test.boxMin.x; x < test.boxMax.x; ++x) visit(glm::ivec3(x, y, z));
}

// `density(cell)` and `material(cell)` read a window cell. NaN densities fail Mean (the sum is
// NaN) and count as not solid; Min and Max skip a NaN after the first cell and fail on a NaN
// first cell, because they keep `d < m ? d : m` (`m < d ? d : m`), which the kernel writes alike.
template <typename Density, typename Material>
bool aggregatePasses(const AggregateTest& test, Density&& density, Material&& material) {
    switch (test.kind) {
    case AggregateKind::Mean: {
        float sum = 0.0f;
        forEachAggregateCell(test, [&](glm::ivec3 cell) { sum = sum + density(cell); });
        return sum >= test.low && sum <= test.high;
    }
    case AggregateKind::Min:
    case AggregateKind::Max: {
        const bool isMin = test.kind == AggregateKind::Min;
        float extreme = density(test.boxMin);
        forEachAggregateCell(test, [&](glm::ivec3 cell) {
            const float d = density(cell);
            extreme = (isMin ? d < extreme : extreme < d) ? d : extreme;
        });
        return extreme >= test.low && extreme <= test.high;
    }
    case AggregateKind::SolidFraction:
    case AggregateKind::MaterialFraction: {
        uint32_t count = 0;
        forEachAggregateCell(test, [&](glm::ivec3 cell) {
            count += test.kind == AggregateKind::SolidFraction ? density(cell) >= kSolidDensity
                                                               : material(cell) == test.material;
        });
        return count >= test.minCount && count <= test.maxCount;
    }
    }
    return false;
}

} // namespace voxc
