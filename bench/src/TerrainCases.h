#pragma once
#include "JsonReporter.h"

#include "voxc/vulkan/Context.h"

#include <vector>

namespace voxc::bench {

// Registers erosion (record n = the grid's side, 512): pipe-model erosion steps on the CPU.
void registerErosion(JsonReporter& reporter);
// Registers terrain_mountain_river (n = the map's side): generateTerrain end to end with the
// preset's schedule truncated at that side's level, on one CPU thread ("host") and, with a
// device, with its erosion steps on the device ("vulkan"); reports cell-steps per second and the
// process's peak RSS.
void registerTerrainSchedule(JsonReporter& reporter, const std::vector<int>& sides, bool host, VulkanContext* device);

} // namespace voxc::bench
