#pragma once
#include "JsonReporter.h"

namespace voxc::bench {

// Registers erosion (record n = the grid's side, 512): pipe-model erosion steps on the CPU.
void registerErosion(JsonReporter& reporter);

} // namespace voxc::bench
