#pragma once
// A triangle mesh as signed distances on the world's voxel lattice (OpenVDB's
// tools::meshToVolume): negative inside, positive outside, in world voxels, exact within `band`
// of the surface and ±band beyond it.
#include "voxc/generators/inputs/MeshFile.h"

#include <glm/vec3.hpp>
#include <cstdint>
#include <utility>
#include <vector>

namespace voxc::inputs {

// World = translate + scale · R(rotate) · p, R = Rz·Ry·Rx of the angles in degrees (x applied
// first).
struct MeshTransform {
    glm::dvec3 translate{0.0};
    glm::dvec3 rotateDegrees{0.0};
    double scale = 1.0;
};

// The mesh's points placed in world voxels; InputError E0102 when one is not finite or beyond
// ±1e7.
std::vector<glm::dvec3> placePoints(const TriangleMesh& mesh, const MeshTransform& transform);

struct DistanceGrid {
    glm::ivec3 min{0};  // world voxel of cell (0, 0, 0); cell (i, j, k) is world voxel min + (i, j, k)
    glm::ivec3 size{0}; // cells per axis
    std::vector<float> values; // x fastest, then y, then z
    float band = 0.0f;
    // Edges of the mesh (after welding equal positions) that border one triangle, or more than
    // two: 0 for a closed, manifold surface.
    int64_t openEdges = 0;
    int64_t nonManifoldEdges = 0;
    // Closed parts (connected through shared vertices, every edge bordering two of their
    // triangles) wound clockwise seen from outside: their signed volume is negative, and they lie
    // in no outward-wound closed part's box (the inner wall of a hollow is wound inward on
    // purpose). Their volume in cubic voxels, together. 0 for a mesh wound as glTF, OBJ and PLY
    // expect.
    int64_t insideOutParts = 0;
    double insideOutVolume = 0.0;
    // Pairs of triangles that share no vertex and cross each other (an edge of one passes through
    // the other; coplanar overlaps and touching are not counted), and the lowest such pair of
    // triangle indices (in the file's order).
    int64_t crossingPairs = 0;
    std::pair<uint32_t, uint32_t> firstCrossing{0, 0};
};

// The grid covers the transformed mesh's box grown by band + 1 voxels. InputError E0012 when it
// would have more than Limits::maxDistanceCells cells, E0102 when a transformed point is not
// finite or beyond ±1e7.
DistanceGrid meshDistances(const TriangleMesh& mesh, const MeshTransform& transform, float band,
                           const Limits& limits = {});

} // namespace voxc::inputs
