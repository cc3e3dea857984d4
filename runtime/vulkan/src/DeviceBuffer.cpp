#include "DeviceBuffer.h"

#include "voxc/core/Errors.h"

#include <fmt/format.h>

namespace voxc::vulkan_detail {

bool unifiedMemory(const VulkanContext::Impl& ctx) {
    return ctx.info.type == DeviceType::Integrated || ctx.info.type == DeviceType::Cpu;
}

namespace {

// Highest-scoring allowed memory type with every required flag, or -1.
int chooseMemoryType(const VulkanContext::Impl& ctx, uint32_t allowedTypes, MemoryUse use) {
    const VkMemoryPropertyFlags required =
        use == MemoryUse::HostAccess ? VkMemoryPropertyFlags(VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) : 0;
    int best = -1, bestScore = -1000;
    for (uint32_t i = 0; i < ctx.memory.memoryTypeCount; ++i) {
        const VkMemoryPropertyFlags flags = ctx.memory.memoryTypes[i].propertyFlags;
        if (!(allowedTypes & (1u << i)) || (flags & required) != required) continue;
        const bool deviceLocal = flags & VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
        int score = 0;
        if (use == MemoryUse::Device) {
            score = deviceLocal ? 4 : 0;
        } else {
            // Host reads of uncached memory (a discrete GPU's BAR window) are very slow.
            if (flags & VK_MEMORY_PROPERTY_HOST_CACHED_BIT) score += 2;
            if (deviceLocal) score += unifiedMemory(ctx) ? 1 : -4;
        }
        if (score > bestScore) {
            best = int(i);
            bestScore = score;
        }
    }
    return best;
}

} // namespace

DeviceBuffer createBuffer(VulkanContext::Impl& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use) {
    DeviceBuffer result;
    result.size = size;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    check(ctx.api.vkCreateBuffer(ctx.device, &info, nullptr, &result.buffer), "vkCreateBuffer");

    VkMemoryRequirements requirements;
    ctx.api.vkGetBufferMemoryRequirements(ctx.device, result.buffer, &requirements);
    const int type = chooseMemoryType(ctx, requirements.memoryTypeBits, use);
    if (type < 0) {
        destroyBuffer(ctx, result);
        throw UserError(fmt::format("the Vulkan device '{}' has no suitable memory type for a {} buffer", ctx.info.name,
                                    use == MemoryUse::HostAccess ? "host-visible" : "device"));
    }
    const VkMemoryType& memoryType = ctx.memory.memoryTypes[type];
    const VkDeviceSize heapSize = ctx.memory.memoryHeaps[memoryType.heapIndex].size;
    if (requirements.size > heapSize) {
        destroyBuffer(ctx, result);
        throw UserError(fmt::format("a {:.1f} MiB buffer does not fit the device's {:.1f} MiB memory heap; use a "
                                    "smaller grid",
                                    double(requirements.size) / (1 << 20), double(heapSize) / (1 << 20)));
    }
    VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    allocate.allocationSize = requirements.size;
    allocate.memoryTypeIndex = uint32_t(type);
    try {
        check(ctx.api.vkAllocateMemory(ctx.device, &allocate, nullptr, &result.memory), "vkAllocateMemory");
        check(ctx.api.vkBindBufferMemory(ctx.device, result.buffer, result.memory, 0), "vkBindBufferMemory");
        result.coherent = memoryType.propertyFlags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        if (use == MemoryUse::HostAccess)
            check(ctx.api.vkMapMemory(ctx.device, result.memory, 0, VK_WHOLE_SIZE, 0, &result.mapped), "vkMapMemory");
    } catch (...) {
        destroyBuffer(ctx, result);
        throw;
    }
    return result;
}

void destroyBuffer(VulkanContext::Impl& ctx, DeviceBuffer& buffer) {
    if (buffer.buffer) ctx.api.vkDestroyBuffer(ctx.device, buffer.buffer, nullptr);
    if (buffer.memory) ctx.api.vkFreeMemory(ctx.device, buffer.memory, nullptr); // also unmaps
    buffer = DeviceBuffer{};
}

void flushForDevice(VulkanContext::Impl& ctx, const DeviceBuffer& buffer) {
    if (buffer.coherent) return;
    VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
    range.memory = buffer.memory;
    range.size = VK_WHOLE_SIZE;
    check(ctx.api.vkFlushMappedMemoryRanges(ctx.device, 1, &range), "vkFlushMappedMemoryRanges");
}

void invalidateForHost(VulkanContext::Impl& ctx, const DeviceBuffer& buffer) {
    if (buffer.coherent) return;
    VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
    range.memory = buffer.memory;
    range.size = VK_WHOLE_SIZE;
    check(ctx.api.vkInvalidateMappedMemoryRanges(ctx.device, 1, &range), "vkInvalidateMappedMemoryRanges");
}

} // namespace voxc::vulkan_detail
