#include "CommandSlot.h"

namespace voxc::vulkan_detail {

CommandSlot createCommandSlot(VulkanContext::Impl& ctx) {
    CommandSlot slot;
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = ctx.queueFamily;
    check(ctx.api.vkCreateCommandPool(ctx.device, &poolInfo, nullptr, &slot.pool), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocate.commandPool = slot.pool;
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    try {
        check(ctx.api.vkAllocateCommandBuffers(ctx.device, &allocate, &slot.commands), "vkAllocateCommandBuffers");
        check(ctx.api.vkCreateFence(ctx.device, &fenceInfo, nullptr, &slot.fence), "vkCreateFence");
    } catch (...) {
        ctx.api.vkDestroyCommandPool(ctx.device, slot.pool, nullptr); // frees its command buffer
        throw;
    }
    return slot;
}

} // namespace voxc::vulkan_detail
