#pragma once
// The sphere brush: smooth CSG on densities (meshing spec §1.7 #8), never a hard write of 0 or 1.
//
// The brush's own density at world voxel p is b = density(sdf_sphere(p, centre, radius), softness),
// evaluated with the same float operations, in the same order, as the grammar's builtins
// (compiler/builtins/src/functions/Sdf.cpp): b = clamp(0.5 - (|p - c| - r) / w, 0, 1), |v| summed
// x, y, z then sqrt. A carve is voxc's `subtract` on densities, d' = min(d, 1 - b); an add is its
// `union`, d' = max(d, b). A density that is not finite counts as 0 (air), as the meshers read it.
// The brush reaches only voxels with b > 0, i.e. |p - c| < r + w/2 (its support); the rest keep
// their bits (min(d, 1) would otherwise clamp densities above 1 wherever the loop happened to pass).
//
// Edits run on the host, on the grid read back from the device or made by the interpreter, so
// `voxc run --edits` and `voxc interp --edits` apply the same bits to the same grids.
#include "voxc/grid/Grid.h"

#include <glm/vec3.hpp>
#include <optional>

namespace voxc {

struct Brush {
    enum class Op { Carve, Add };
    Op op = Op::Carve;
    glm::vec3 center{0.0f};
    float radius = 1.0f;   // > 0
    float softness = 1.0f; // the ramp width w of density(), > 0
    // Add only: the material id given to every voxel the add makes denser; 0 keeps their own.
    uint8_t material = 0;
};

// b at world voxel position p.
float brushDensity(const Brush& brush, glm::ivec3 p);
// The density d becomes under the brush where its own density is b.
float brushed(Brush::Op op, float d, float b);

// A box of grid-local voxels, both corners inclusive.
struct VoxelBox {
    glm::ivec3 first{0};
    glm::ivec3 last{-1};
};

// Applies the brush to every voxel of its support inside the grid and returns the box of the
// voxels whose density bits (or material) changed (nullopt when none did: the edit was a no-op).
// Materials are kept, except where an add with a material makes a voxel denser. A grid with tile
// ranges keeps them, brought up to date over the changed box (so its meshers still skip uniform tiles).
std::optional<VoxelBox> applyBrush(ChunkedGrid& grid, const Brush& brush);
// The same on a dense grid whose voxel (0,0,0) is at world position `origin` (the interpreter's).
std::optional<VoxelBox> applyBrush(DenseGrid& grid, glm::ivec3 origin, const Brush& brush);

} // namespace voxc
