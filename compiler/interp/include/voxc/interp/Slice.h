#pragma once
// A text picture of one layer of a grid, for debugging rule files and for golden tests.
#include "voxc/grid/Grid.h"
#include "voxc/program/Program.h"

#include <functional>
#include <string>
#include <string_view>

namespace voxc {

// The layer where coordinate `axis` (0 x, 1 y, 2 z) equals `index`. The picture's columns run
// along the lower remaining axis and its rows along the higher one, top row = highest
// coordinate (so a z layer looks like the printed rule layout). A legend line comes first.
// Characters: ' ' == 0, '.' (0, 0.25), ':' [0.25, 0.5), '+' [0.5, 1), '#' == 1,
// '<' below 0, '>' above 1, '?' NaN. Throws UserError when axis or index is out of range.
std::string renderSlice(const DenseGrid& grid, int axis, int index);

// The same layer's materials: ' ' a voxel that is not solid (density <= iso, whatever its
// material), '.' a solid voxel of material `none`, and one character per declared material
// (its name's first letter where free), listed in the legend line.
std::string renderMaterialSlice(const Program& program, const DenseGrid& grid, float iso, int axis, int index);

// The layout every slice shares: a header line naming the layer and its axes, `legend` (one
// line), then one row per line, one character per voxel from `cell` (given the voxel's
// grid-local position). Throws UserError when axis or index is out of range.
std::string renderLayer(glm::ivec3 size, int axis, int index, std::string_view legend,
                        const std::function<char(glm::ivec3)>& cell);

} // namespace voxc
