#pragma once
// Light that reaches each vertex of a mesh, measured in the voxel grid the mesh came from, so
// that `voxc render` shows creases, tunnels and overhangs rather than flat shading:
// - ambient occlusion: the cosine-weighted share of a fixed set of short rays over the vertex's
//   hemisphere that leave the rock within kOcclusionReach voxels;
// - sun visibility: 1 where a ray towards the light leaves the grid's box without entering rock,
//   0 where rock blocks it (a hard shadow, softened by interpolation across each triangle).
// Rays march in whole-voxel steps and read the nearest voxel, with the meshers' rule for solid
// (density > iso; outside the grid and non-finite values are air), so the result depends only on
// the grid, the mesh and the light: the same picture on every device.
#include "voxc/grid/Grid.h"
#include "voxc/mesh/Mesh.h"

#include <glm/glm.hpp>
#include <vector>

namespace voxc::rendering {

inline constexpr float kOcclusionReach = 12.0f;

struct LightingOptions {
    bool ambientOcclusion = true;
    bool shadows = true;
    glm::vec3 towardsLight{0.0f, 1.0f, 0.0f}; // unit length
    float iso = 0.5f;
};

// Per vertex, in [0, 1]: 1 = fully open. A term that is off is 1 everywhere.
struct VertexLight {
    std::vector<float> ambient;
    std::vector<float> sun;
};

// `grid` holds the voxels of `mesh`: world position p reads grid voxel p - gridOrigin. Runs on
// every hardware thread; the result does not depend on how many there are.
VertexLight lightVertices(const Mesh& mesh, const DenseGrid& grid, glm::ivec3 gridOrigin, const LightingOptions& options);

} // namespace voxc::rendering
