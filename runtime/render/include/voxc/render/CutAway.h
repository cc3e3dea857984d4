#pragma once
// `voxc render --cut`: rock removed from the grid before it is meshed, so that caves and tunnels
// show from outside as in a sectioned model. The cut faces are meshed like any other surface and
// take the material of the rock they cut.
#include "voxc/grid/Grid.h"

#include <glm/glm.hpp>
#include <string_view>

namespace voxc::rendering {

// The world voxels to remove: those inside [min, max) on every axis (a half-space is a box that
// reaches past the grid on the other sides).
struct CutAway {
    glm::ivec3 min{0};
    glm::ivec3 max{0};
};

// "x>N", "x<N" (likewise y, z): every voxel whose world coordinate on that axis is greater (less)
// than N; or "MINX,MINY,MINZ:MAXX,MAXY,MAXZ": a box in world voxels, each max excluded (the
// spelling of --region). UserError naming the spec and the accepted forms otherwise.
CutAway parseCutAway(std::string_view spec);

// Sets the removed voxels of `grid` to air (density 0, no material); returns how many there were.
size_t applyCutAway(ChunkedGrid& grid, const CutAway& cut);

} // namespace voxc::rendering
