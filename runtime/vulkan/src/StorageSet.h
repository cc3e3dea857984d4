#pragma once
// What every group of voxc compute pipelines shares: one descriptor set and a push-constant
// block; the package's kernels bind storage buffers alone (createStorageSet), the marching-cubes
// passes texel buffers as well (GpuMesherPipelines.cpp).
#include "ContextImpl.h"

#include <cstdint>
#include <span>
#include <string>

namespace voxc::vulkan_detail {

struct StorageSet {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
};

// Set 0 with a storage buffer at each of `bindings`, and `pushBytes` of push constants. Fills
// `out` step by step, so destroyStorageSet cleans up after a failure part way.
void createStorageSet(VulkanContext::Impl& ctx, std::span<const uint32_t> bindings, uint32_t pushBytes,
                      StorageSet& out);
// The same for bindings of any descriptor types (one descriptor each, compute stage).
void createDescriptorSet(VulkanContext::Impl& ctx, std::span<const VkDescriptorSetLayoutBinding> bindings,
                         uint32_t pushBytes, StorageSet& out);
// Only the layouts of a storage set (no pool, no set), `setLayout` first.
void createStorageLayout(VulkanContext::Impl& ctx, std::span<const uint32_t> bindings, uint32_t pushBytes,
                         VkDescriptorSetLayout& setLayout, VkPipelineLayout& layout);
// A compute pipeline of `spirv` over `layout`; InternalError naming `what` when the driver rejects it.
VkPipeline createComputePipeline(VulkanContext::Impl& ctx, VkPipelineLayout layout, std::span<const uint32_t> spirv,
                                 const std::string& what);
// Points binding bindings[i] at buffers[i], whole.
void writeStorageBindings(VulkanContext::Impl& ctx, VkDescriptorSet set, std::span<const uint32_t> bindings,
                          std::span<const VkBuffer> buffers);
void destroyStorageSet(VulkanContext::Impl& ctx, StorageSet& set);

} // namespace voxc::vulkan_detail
