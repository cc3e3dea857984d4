#pragma once
#include "JsonReporter.h"

#include "voxc/vulkan/Context.h"

namespace voxc::bench {

// Registers lsystem_carve: grammar (3), four expansions, carved by an lsystem_cave with the
// default brush into a 128x32x128 rock grid in 32^3 chunks (record n = 32, the chunk size), on
// Vulkan and in the interpreter; each record also gives chunks (those the carve's interval
// analysis leaves to evaluate) and ms_per_chunk. `context` is null when Vulkan is not benched.
void registerLsystemCarve(JsonReporter& reporter, VulkanContext* context, bool interp);

} // namespace voxc::bench
