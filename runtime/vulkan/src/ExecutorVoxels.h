#pragma once
// The device buffers a VulkanExecutor's run() leaves behind, for the GPU mesher (GpuMesher.cpp),
// which meshes them where they are instead of reading the densities back first.
#include "ContextImpl.h"

namespace voxc::vulkan_detail {

struct ExecutorVoxels {
    VulkanContext::Impl* context = nullptr;
    VkBuffer voxels = VK_NULL_HANDLE;    // float densities, chunk-major (ChunkLayout::address)
    VkBuffer materials = VK_NULL_HANDLE; // uint ids at the same addresses when hasMaterials, else one element
    bool hasMaterials = false;
    bool hasRun = false; // run() has filled the buffers
};

} // namespace voxc::vulkan_detail
