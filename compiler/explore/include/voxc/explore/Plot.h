#pragma once
// The exploration plot: one panel per descriptor (solid fraction, surface area, mean pairwise
// IoU) against the swept parameter, each with the mean over runs as a line with markers and a
// shaded band of +/- one standard deviation. Text uses a built-in 5x7 font (capitals only).
#include "voxc/explore/Explore.h"
#include "voxc/explore/Image.h"

#include <string_view>

namespace voxc::explore {

Image plotExploration(const ExploreResult& result, std::string_view title);

} // namespace voxc::explore
