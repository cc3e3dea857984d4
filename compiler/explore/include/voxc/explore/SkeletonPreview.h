#pragma once
// Pictures for choosing among L-system variants (`voxc evolve`): a skeleton seen from above and
// from the side, and a contact sheet of several such previews with their labels.
#include "voxc/explore/Image.h"
#include "voxc/generators/lsystem/Turtle.h"

#include <string>
#include <vector>

namespace voxc::explore {

// Top view (x right, z down) beside a side view (x right, y up) at one scale that fits both, so
// proportions are kept: tunnels, rooms and untyped segments in their own colours, connection
// lines in another, endpoints as dots; `caption` under the views. `viewSize` pixels per view.
Image renderSkeletonPreview(const lsystem::Skeleton& skeleton, const std::string& caption, int viewSize = 240);

// The previews in rows of `columns`, each with its label above it.
Image contactSheet(const std::vector<Image>& previews, const std::vector<std::string>& labels, int columns);

} // namespace voxc::explore
