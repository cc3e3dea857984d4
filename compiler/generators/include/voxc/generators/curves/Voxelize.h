#pragma once
// Voxelisation (spec A3.3): exact triangle/cube overlap in double precision at plan time; every
// overlapped solve cell gathers the triangles' values in fixed triangle order into dense float32
// constraint fields (the Dirichlet data of the solves).
#include "voxc/generators/curves/Curve.h"
#include "voxc/generators/curves/Grid.h"

#include <array>

namespace voxc::curves {

// Exact separating-axis test of a triangle against the axis-aligned cube of side `side` centred at `centre`.
bool triangleOverlapsCube(const std::array<glm::dvec3, 3>& triangle, const glm::dvec3& centre, double side);

// The point of the triangle closest to `p`, as barycentric weights of its three vertices.
glm::dvec3 closestBarycentric(const std::array<glm::dvec3, 3>& triangle, const glm::dvec3& p);

enum CellFlags : uint8_t { kInNormals = 1, kInParams = 2, kInSurface = 4 }; // Omega_N, Omega_R, Omega_S

struct Constraints {
    Box box;
    std::vector<uint8_t> flags;           // CellFlags per cell
    Field3 normalX, normalY, normalZ;     // N0 on Omega_N, unit
    Field3 amplitude, roughness;          // alpha0, beta0 on Omega_R
    std::vector<uint16_t> material;       // m0 on Omega_R
    Field3 surface;                       // S0 on Omega_S

    explicit Constraints(const Box& box_);
};

enum class SeedValue { PlaneDistance, Zero }; // A2.5: the default keeps the surface on the curve

// Validates the box and curves (LimitError, ParameterError) and gathers every curve's triangles.
Constraints voxelize(const std::vector<FeatureCurve>& curves, const Box& box, SeedValue seedValue, const Limits& limits);

// The box checks voxelize makes, for callers that build Constraints themselves.
void checkBox(const Box& box, const Limits& limits);

} // namespace voxc::curves
