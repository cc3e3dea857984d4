#pragma once
#include "JsonReporter.h"

namespace voxc::bench {

// Registers lsystem_expand (record n = the expanded string's length).
void registerLsystemExpand(JsonReporter& reporter);

} // namespace voxc::bench
