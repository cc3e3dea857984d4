#pragma once
// The device buffers a VulkanExecutor's run() leaves behind, for the GPU mesher (GpuMesher.cpp),
// which meshes them where they are instead of reading the densities back first.
#include "ContextImpl.h"
#include "DeviceBuffer.h"
#include "voxc/grid/Grid.h"

#include <optional>

namespace voxc::vulkan_detail {

struct ExecutorVoxels {
    VulkanContext::Impl* context = nullptr;
    VkBuffer voxels = VK_NULL_HANDLE;    // float densities, chunk-major (ChunkLayout::address)
    VkBuffer materials = VK_NULL_HANDLE; // uint ids at the same addresses when hasMaterials, else one element
    bool hasMaterials = false;
    bool hasRun = false; // run() has filled the buffers
    // The tile ranges of the densities the last run() read back (ChunkedGrid::loadDensities);
    // empty when it did not read them back. Points into the executor, so it follows every run.
    const std::optional<TileRanges>* tileRanges = nullptr;
    // The materials' memory where it is mapped (a device whose memory is the host's: results are
    // not staged) and holds materials; else null. The mesher votes the triangles' materials on the
    // host from it.
    const DeviceBuffer* mappedMaterials = nullptr;
};

} // namespace voxc::vulkan_detail
