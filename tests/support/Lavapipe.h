#pragma once
// The lavapipe device the Vulkan tests of one binary share: created on first use, so a binary
// pays Vulkan's start-up once, and every test runs on the same CPU device whatever GPU is present.
#include "voxc/vulkan/Context.h"

namespace voxc::test {

inline VulkanContext& lavapipe() {
    static VulkanContext context(ContextOptions{.device = "lavapipe"});
    return context;
}

} // namespace voxc::test
