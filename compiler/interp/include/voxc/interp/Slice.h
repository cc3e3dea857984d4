#pragma once
// A text picture of one layer of a grid, for debugging rule files and for golden tests.
#include "voxc/grid/Grid.h"

#include <string>

namespace voxc {

// The layer where coordinate `axis` (0 x, 1 y, 2 z) equals `index`. The picture's columns run
// along the lower remaining axis and its rows along the higher one, top row = highest
// coordinate (so a z layer looks like the printed rule layout). A legend line comes first.
// Characters: ' ' == 0, '.' (0, 0.25), ':' [0.25, 0.5), '+' [0.5, 1), '#' == 1,
// '<' below 0, '>' above 1, '?' NaN. Throws UserError when axis or index is out of range.
std::string renderSlice(const DenseGrid& grid, int axis, int index);

} // namespace voxc
