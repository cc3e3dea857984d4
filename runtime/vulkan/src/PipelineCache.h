#pragma once
// The device's VkPipelineCache, kept in a file between runs so a second run of the same kernels
// skips the driver's pipeline compilation where the driver caches it (issue "Speed", part 1).
#include "ContextImpl.h"

#include <string>

namespace voxc {

// Creates `ctx.pipelineCache`, seeded from `directory`'s file for this device and driver when
// that file is whole and made by this device and driver (its checksum and Vulkan's cache header
// match); a missing, corrupted or foreign file starts an empty cache. Empty `directory`: no file.
void openPipelineCache(VulkanContext::Impl& ctx, const std::string& directory);

// Writes the cache's data back (temp file and rename) when it changed; a failure to write is
// ignored, since the cache only saves time.
void savePipelineCache(VulkanContext::Impl& ctx) noexcept;

} // namespace voxc
