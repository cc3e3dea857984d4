#pragma once
// The lavapipe device the Vulkan tests of one binary share: created on first use, so a binary
// pays Vulkan's start-up once, and every test runs on the same CPU device whatever GPU is present.
#include "voxc/stages/Pipeline.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"

namespace voxc::test {

inline VulkanContext& lavapipe() {
    static VulkanContext context(ContextOptions{.device = "lavapipe"});
    return context;
}

// The grid a run of `program` leaves on lavapipe.
inline DenseGrid runOnLavapipe(const Program& program, const ExecutorOptions& options = {}) {
    VulkanExecutor executor(lavapipe(), compileProgram(program, {}), options);
    return executor.run().grid.toDense();
}

} // namespace voxc::test
