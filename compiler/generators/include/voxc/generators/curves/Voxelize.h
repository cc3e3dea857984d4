#pragma once
// Voxelisation (spec A3.3): exact triangle/cube overlap in double precision at plan time; every
// overlapped solve cell gathers the triangles' values in fixed triangle order into dense float32
// constraint fields (the Dirichlet data of the solves).
#include "voxc/generators/curves/Curve.h"
#include "voxc/generators/curves/Grid.h"

#include <array>
#include <memory>
#include <string>

namespace voxc::curves {

// Exact separating-axis test of a triangle against the axis-aligned cube of side `side` centred at `centre`.
bool triangleOverlapsCube(const std::array<glm::dvec3, 3>& triangle, const glm::dvec3& centre, double side);

// The point of the triangle closest to `p`, as barycentric weights of its three vertices.
glm::dvec3 closestBarycentric(const std::array<glm::dvec3, 3>& triangle, const glm::dvec3& p);

enum CellFlags : uint8_t { kInNormals = 1, kInParams = 2, kInSurface = 4 }; // Omega_N, Omega_R, Omega_S

// The cells a voxelisation constrains, each with its gathered values (what Constraints holds
// there; every other cell of the box is 0): a few bytes per cell near a curve rather than 27 per
// box cell, so the checker keeps this and the solve builds the dense fields.
struct GatheredConstraints {
    struct Cell {
        uint64_t index = 0; // Box::index
        uint8_t flags = 0;  // CellFlags, never 0
        uint16_t material = 0;
        glm::vec3 normal{0.0f};
        float amplitude = 0.0f, roughness = 0.0f, surface = 0.0f;
    };
    Box box;
    std::vector<Cell> cells; // each cell once, in no particular order

    bool anySurface() const; // Omega_S is not empty
};

struct Constraints {
    Box box;
    std::vector<uint8_t> flags;           // CellFlags per cell
    Field3 normalX, normalY, normalZ;     // N0 on Omega_N, unit
    Field3 amplitude, roughness;          // alpha0, beta0 on Omega_R
    std::vector<uint16_t> material;       // m0 on Omega_R
    Field3 surface;                       // S0 on Omega_S

    explicit Constraints(const Box& box_); // every cell unconstrained
    explicit Constraints(const GatheredConstraints& gathered);
};

enum class SeedValue { PlaneDistance, Zero }; // A2.5: the default keeps the surface on the curve

// An imported surface voxelised with the curves (Becher et al. §3.3, "Heightmaps and Meshes"):
// a mesh's triangles, or a heightmap's proxy mesh, in box-local voxels. Both are seed surfaces
// (they pin N, the parameters and S) whose normal is the triangle's face normal.
struct InputSurface {
    enum class Kind : uint8_t { Mesh, Heightmap }; // the priority after the curves, highest first
    Kind kind = Kind::Mesh;
    std::string name; // the block's, for messages
    // Mesh: the triangles, wound counter-clockwise seen from outside, so (v1 - v0) x (v2 - v0)
    // points into the air.
    std::vector<std::array<glm::dvec3, 3>> triangles;
    // Heightmap: the surface's box-local y over the columns x = -1 .. size.x, z = -1 .. size.z
    // of the box (size.x + 2 per row, x fastest); each quad of four neighbouring columns is two
    // triangles facing up.
    std::vector<double> heights;
};

// What every input's triangles carry (the files hold no noise parameters or materials) and the
// dead zone: a lower-priority input gathers only at cells farther than `deadZone` (Chebyshev,
// voxels) from every cell a higher-priority one hit, curves over meshes over heightmaps.
struct InputOptions {
    int32_t deadZone = 2;
    double amplitude = 0.0, roughness = 0.5;
    uint16_t material = 0;
};

// Validates the box and curves (LimitError, ParameterError) and gathers every curve's triangles,
// then the meshes' where no curve is near, then the heightmaps' where neither is. Each cell sums
// its triangles' values in the order given (curves, then inputs); the box's two halves in z are
// gathered on two threads, which changes no bit.
GatheredConstraints gatherConstraints(const std::vector<FeatureCurve>& curves, const Box& box, SeedValue seedValue,
                                      const Limits& limits,
                                      const std::vector<std::shared_ptr<const InputSurface>>& inputs = {},
                                      const InputOptions& inputOptions = {});
// Constraints(gatherConstraints(...)).
Constraints voxelize(const std::vector<FeatureCurve>& curves, const Box& box, SeedValue seedValue, const Limits& limits,
                     const std::vector<std::shared_ptr<const InputSurface>>& inputs = {},
                     const InputOptions& inputOptions = {});

// The box checks voxelize makes, for callers that build Constraints themselves.
void checkBox(const Box& box, const Limits& limits);

} // namespace voxc::curves
