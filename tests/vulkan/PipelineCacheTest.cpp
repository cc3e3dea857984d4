// The pipeline cache file: written when a context with a cache directory ends, read by the next
// one, and a damaged or foreign file is ignored (the run is the same) and replaced.
#include "TestKernels.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <unistd.h>

using namespace voxc;
using namespace voxc::test;

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> cacheFiles(const fs::path& directory) {
    std::vector<fs::path> out;
    if (fs::exists(directory))
        for (const auto& entry : fs::directory_iterator(directory))
            if (entry.path().filename().string().starts_with("pipelines-")) out.push_back(entry.path());
    return out;
}

std::vector<float> runWithCache(const fs::path& directory) {
    VulkanContext context(ContextOptions{.device = "lavapipe", .pipelineCacheDirectory = directory.string()});
    const KernelPackage package = makePackage(makeWorld({24, 20, 16}, {3, -2, 5}, 8), true,
                                              {TestGrammar{.sweeps = {{TestKernel::Shift, {2, 1, 1}}}}});
    VulkanExecutor executor(context, package);
    return executor.run().grid.toDense().data();
}

TEST(vulkan_PipelineCache, WrittenThenReadAndDamageIsIgnored) {
    const fs::path directory = fs::temp_directory_path() / ("voxc-pipeline-cache-" + std::to_string(::getpid()));
    fs::remove_all(directory);
    const std::vector<float> reference = runWithCache(directory);
    const std::vector<fs::path> files = cacheFiles(directory);
    ASSERT_EQ(files.size(), 1u);
    const auto size = fs::file_size(files[0]);
    // The tag and hash, then Vulkan's 32-byte header; lavapipe stores no more (Mesa keeps its
    // compiled shaders in its own disk cache), a GPU driver stores its pipelines after it.
    EXPECT_GE(size, 16u + 32u);
    EXPECT_EQ(runWithCache(directory), reference);

    const std::string damaged[] = {"voxcpc01 but not a cache", "", std::string(4096, '\xff')};
    for (const std::string& bytes : damaged) {
        std::ofstream(files[0], std::ios::binary | std::ios::trunc) << bytes;
        EXPECT_EQ(runWithCache(directory), reference);
        EXPECT_EQ(cacheFiles(directory).size(), 1u);
        EXPECT_EQ(fs::file_size(files[0]), size); // replaced by a whole one
    }
    fs::remove_all(directory);
}

} // namespace
