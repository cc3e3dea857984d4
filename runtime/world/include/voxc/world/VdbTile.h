#pragma once
// One tile as an OpenVDB file (Houdini, Blender, pyopenvdb and OpenVDB's own tools read it): a
// float grid "density" (class fog volume) and a float grid "material" holding the ids 0..255
// exactly, both with background 0, voxel (i, j, k) at world
// coordinate (i, j, k); every 8^3 block of one value is stored as a constant tile (pruned). The
// file's UUID is made from its contents, so the same voxels always give the same bytes.
#include "voxc/grid/Grid.h"

#include <string>

namespace voxc::world {

// The file's bytes for `grid`, whose voxel (0,0,0) is at world coordinate `worldMin`.
std::string tileVdbBytes(const DenseGrid& grid, glm::ivec3 worldMin);

// Reads such a file back into a grid of `size` whose voxel (0,0,0) is at `worldMin`.
DenseGrid readTileVdb(const std::string& path, glm::ivec3 worldMin, glm::ivec3 size);

} // namespace voxc::world
