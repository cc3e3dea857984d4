#pragma once
// A resettable command pool with one primary command buffer and a fence: what a component that
// records its own submissions and waits for each owns (the GPU mesher, the solve runner, the
// renderer). The owner destroys the pool and the fence with the device's other objects.
#include "ContextImpl.h"

namespace voxc::vulkan_detail {

struct CommandSlot {
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer commands = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
};

CommandSlot createCommandSlot(VulkanContext::Impl& ctx);

} // namespace voxc::vulkan_detail
