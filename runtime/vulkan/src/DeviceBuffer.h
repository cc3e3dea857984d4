#pragma once
// A buffer with its own memory allocation (voxc allocates a handful, so no sub-allocator).
#include "ContextImpl.h"

namespace voxc::vulkan_detail {

enum class MemoryUse {
    Device,      // device-local, not mapped
    HostAccess,  // mapped; device-local too when the device has such memory (unified/CPU devices)
};

struct DeviceBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr; // HostAccess only
    bool coherent = false;
};

// The device's memory is the host's (an integrated GPU or a CPU device such as lavapipe): its
// device-local memory is as fast to map and read as any.
bool unifiedMemory(const VulkanContext::Impl& ctx);
// Memory-type choice: `use` decides required and preferred property flags; throws UserError
// when no memory type fits or the allocation is refused for lack of memory.
DeviceBuffer createBuffer(VulkanContext::Impl& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use);
void destroyBuffer(VulkanContext::Impl& ctx, DeviceBuffer& buffer);
// Host writes -> device (flush) and device writes -> host (invalidate) for non-coherent memory.
void flushForDevice(VulkanContext::Impl& ctx, const DeviceBuffer& buffer);
void invalidateForHost(VulkanContext::Impl& ctx, const DeviceBuffer& buffer);

} // namespace voxc::vulkan_detail
