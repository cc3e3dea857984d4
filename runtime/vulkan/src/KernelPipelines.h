#pragma once
// The compute pipelines of a package and the one descriptor set they share
// (the kBinding* buffers of KernelPackage.h; push constants: PushBlock).
#include "StorageSet.h"
#include "voxc/codegen/KernelPackage.h"

#include <array>
#include <vector>

namespace voxc::vulkan_detail {

constexpr uint32_t kKernelBindingCount = 14; // bindings 0..13

struct KernelPipelines : StorageSet {
    std::vector<VkPipeline> pipelines; // one per Kernel, same order
    bool shared = false;               // the context owns them (ContextOptions::shareKernelPipelines)
};

// Creates the kernels' pipelines on the host's threads; `out` holds every one made (null where
// none), so destroyPipelines cleans up after a failure. With ContextOptions::shareKernelPipelines
// a kernel whose SPIR-V an earlier executor had gets that pipeline. A kernel the driver rejects
// is an InternalError naming the kernel (the first such in kernel order).
void createPipelines(VulkanContext::Impl& ctx, const std::vector<Kernel>& kernels, KernelPipelines& out);
// `byBinding[b]` is the buffer of binding b.
void bindBuffers(VulkanContext::Impl& ctx, const KernelPipelines& pipelines,
                 const std::array<VkBuffer, kKernelBindingCount>& byBinding);
void destroyPipelines(VulkanContext::Impl& ctx, KernelPipelines& pipelines);

} // namespace voxc::vulkan_detail
