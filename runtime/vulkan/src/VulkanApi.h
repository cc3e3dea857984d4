#pragma once
// The Vulkan entry points voxc uses, resolved at run time from the loader library. voxc opens
// the loader with dlopen instead of linking it so that a machine without Vulkan gets a
// UserError from `voxc run` (and every other command still works) instead of a failed start.
#include <vulkan/vulkan.h>

#include <string>

namespace voxc::vulkan_detail {

#define VOXC_VK_GLOBAL_FUNCTIONS(X)              \
    X(vkCreateInstance)                          \
    X(vkEnumerateInstanceLayerProperties)        \
    X(vkEnumerateInstanceExtensionProperties)

#define VOXC_VK_INSTANCE_FUNCTIONS(X)            \
    X(vkDestroyInstance)                         \
    X(vkEnumeratePhysicalDevices)                \
    X(vkGetPhysicalDeviceProperties)             \
    X(vkGetPhysicalDeviceQueueFamilyProperties)  \
    X(vkGetPhysicalDeviceMemoryProperties)       \
    X(vkGetPhysicalDeviceFeatures)               \
    X(vkCreateDevice)                            \
    X(vkGetDeviceProcAddr)

#define VOXC_VK_DEBUG_FUNCTIONS(X)               \
    X(vkCreateDebugUtilsMessengerEXT)            \
    X(vkDestroyDebugUtilsMessengerEXT)

#define VOXC_VK_DEVICE_FUNCTIONS(X)              \
    X(vkDestroyDevice)                           \
    X(vkGetDeviceQueue)                          \
    X(vkDeviceWaitIdle)                          \
    X(vkQueueSubmit)                             \
    X(vkCreateBuffer)                            \
    X(vkDestroyBuffer)                           \
    X(vkCreateBufferView)                        \
    X(vkDestroyBufferView)                       \
    X(vkGetBufferMemoryRequirements)             \
    X(vkAllocateMemory)                          \
    X(vkFreeMemory)                              \
    X(vkBindBufferMemory)                        \
    X(vkMapMemory)                               \
    X(vkUnmapMemory)                             \
    X(vkFlushMappedMemoryRanges)                 \
    X(vkInvalidateMappedMemoryRanges)            \
    X(vkCreateShaderModule)                      \
    X(vkDestroyShaderModule)                     \
    X(vkCreateDescriptorSetLayout)               \
    X(vkDestroyDescriptorSetLayout)              \
    X(vkCreatePipelineLayout)                    \
    X(vkDestroyPipelineLayout)                   \
    X(vkCreateComputePipelines)                  \
    X(vkCreatePipelineCache)                     \
    X(vkDestroyPipelineCache)                    \
    X(vkGetPipelineCacheData)                    \
    X(vkDestroyPipeline)                         \
    X(vkCreateDescriptorPool)                    \
    X(vkDestroyDescriptorPool)                   \
    X(vkAllocateDescriptorSets)                  \
    X(vkUpdateDescriptorSets)                    \
    X(vkCreateCommandPool)                       \
    X(vkDestroyCommandPool)                      \
    X(vkAllocateCommandBuffers)                  \
    X(vkResetCommandBuffer)                      \
    X(vkBeginCommandBuffer)                      \
    X(vkEndCommandBuffer)                        \
    X(vkCreateFence)                             \
    X(vkDestroyFence)                            \
    X(vkWaitForFences)                           \
    X(vkResetFences)                             \
    X(vkCmdBindPipeline)                         \
    X(vkCmdBindDescriptorSets)                   \
    X(vkCmdPushConstants)                        \
    X(vkCmdDispatch)                             \
    X(vkCmdDispatchIndirect)                     \
    X(vkCmdPipelineBarrier)                      \
    X(vkCmdCopyBuffer)                           \
    X(vkCmdFillBuffer)

#define VOXC_VK_DECLARE(name) PFN_##name name = nullptr;

struct VulkanApi {
    PFN_vkGetInstanceProcAddr vkGetInstanceProcAddr = nullptr;
    VOXC_VK_GLOBAL_FUNCTIONS(VOXC_VK_DECLARE)
    VOXC_VK_INSTANCE_FUNCTIONS(VOXC_VK_DECLARE)
    VOXC_VK_DEBUG_FUNCTIONS(VOXC_VK_DECLARE)
    VOXC_VK_DEVICE_FUNCTIONS(VOXC_VK_DECLARE)
};

#undef VOXC_VK_DECLARE

// Opens the loader (kept open for the life of the process) and resolves the global functions.
// Throws UserError naming the library when it cannot be opened.
VulkanApi loadGlobalApi(const std::string& loaderLibrary);
// Resolves instance-level functions; the debug-utils pair only when `debugUtils` is set.
void loadInstanceApi(VulkanApi& api, VkInstance instance, bool debugUtils);
void loadDeviceApi(VulkanApi& api, VkDevice device);

// "VK_ERROR_OUT_OF_DEVICE_MEMORY" etc.
const char* resultName(VkResult result);
// Throws InternalError ("<what> failed: <result>") unless result is VK_SUCCESS; out-of-memory
// results become UserErrors because the user can fix them with a smaller grid.
void check(VkResult result, const char* what);

} // namespace voxc::vulkan_detail
