#pragma once
// What VulkanContext holds, shared with the executor (private to voxc_vulkan).
#include "VulkanApi.h"
#include "voxc/vulkan/Context.h"

#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace voxc {

struct VulkanContext::Impl {
    vulkan_detail::VulkanApi api;
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memory{};
    DeviceInfo info;
    bool validation = false;
    bool shaderFloat64 = false; // enabled when the device has it (the GPU mesher's crossings need it)
    // Every pipeline is created through it; loaded from and saved to a file when the context's
    // options name a cache directory (PipelineCache.cpp), else it lives as long as the context.
    VkPipelineCache pipelineCache = VK_NULL_HANDLE;
    std::string pipelineCacheFile;      // empty: not saved
    std::vector<char> pipelineCacheLoaded; // what the file held, to skip a save that changes nothing

    // ContextOptions::shareKernelPipelines: the kernels' pipelines by SPIR-V (KernelPipelines.cpp),
    // destroyed with the context. An executor binds its own pipeline layout, which is defined
    // exactly as the one a shared pipeline was created with, so Vulkan counts them compatible.
    bool shareKernelPipelines = false;
    std::mutex kernelPipelineMutex;
    std::map<std::vector<uint32_t>, VkPipeline> kernelPipelines;
    VkPipelineLayout kernelPipelineLayout = VK_NULL_HANDLE; // what the shared pipelines were created with
    VkDescriptorSetLayout kernelSetLayout = VK_NULL_HANDLE;
    KernelPipelineCounts kernelPipelineCounts;

    mutable std::mutex messageMutex; // the layer may call back from driver threads
    std::vector<ValidationMessage> messages;

    Impl() = default;
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    ~Impl();
};

} // namespace voxc
