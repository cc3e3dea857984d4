#pragma once
// The lavapipe device the Vulkan tests of one binary share: created on first use, so a binary
// pays Vulkan's start-up once, and every test runs on the same CPU device whatever GPU is present.
#include "GridCompare.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace voxc::test {

inline VulkanContext& lavapipe() {
    static VulkanContext context(ContextOptions{.device = "lavapipe"});
    return context;
}

// lavapipe with the validation layer, for the tests that ask it to stay quiet.
inline VulkanContext& validatedLavapipe() {
    static VulkanContext context(ContextOptions{.device = "lavapipe", .validation = true});
    return context;
}

// Every message the validation layer gave `context` so far is a failure; the list is cleared.
inline void expectNoValidationMessages(VulkanContext& context = validatedLavapipe()) {
    for (const ValidationMessage& m : context.validationMessages()) ADD_FAILURE() << m.text;
    context.clearValidationMessages();
}

// The grid a run of `program` leaves on lavapipe.
inline DenseGrid runOnLavapipe(const Program& program, const ExecutorOptions& options = {}) {
    VulkanExecutor executor(lavapipe(), compileProgram(program, {}), options);
    return executor.run().grid.toDense();
}

// `program` on lavapipe at chunk sizes 8, 16 and 32: every grid equals `expected`, densities bit
// for bit and materials id for id.
inline void expectLavapipeMatchesAtEveryChunkSize(Program program, const DenseGrid& expected) {
    for (int chunk : {8, 16, 32}) {
        SCOPED_TRACE(fmt::format("chunk {}", chunk));
        program.world.chunkSize = chunk;
        EXPECT_EQ(countVoxelDifferences(expected, runOnLavapipe(program)), 0u);
    }
}

} // namespace voxc::test
