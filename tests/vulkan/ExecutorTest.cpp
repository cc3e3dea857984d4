#include "TestKernels.h"
#include "voxc/core/Errors.h"
#include "voxc/vulkan/DispatchPlan.h"
#include "voxc/vulkan/Executor.h"

#include <gtest/gtest.h>

#include <optional>

using namespace voxc;
using namespace voxc::test;

namespace {

const glm::ivec3 kOrigins[] = {{0, 0, 0}, {-37, -5, -100}, {100003, 7, -65541}};
const int32_t kChunkSizes[] = {8, 16, 32};

// Two grammars; the first mixes an order-sensitive sweep with a strided one inside bounds.
std::vector<TestGrammar> mixedGrammars() {
    TestGrammar first;
    first.iterations = 3;
    first.boundsMin = {2, 1, 0};
    first.boundsMax = {33, 19, 17};
    first.sweeps = {{TestKernel::Shift, {2, 1, 1}}, {TestKernel::AddOne, {1, 2, 1}}, {TestKernel::AddOne, {2, 2, 2}}};
    TestGrammar second;
    second.iterations = 2;
    second.stride = {2, 3, 1};
    second.sweeps = {{TestKernel::Shift, {3, 1, 2}}};
    return {first, second};
}

const glm::ivec3 kGridSize{37, 21, 19}; // not a multiple of any chunk size

RunResult runPackage(const KernelPackage& package, const ExecutorOptions& options = {},
                     const ContextOptions& contextOptions = {}) {
    VulkanContext context(contextOptions);
    VulkanExecutor executor(context, package, options);
    return executor.run();
}

void expectEqualGrids(const DenseGrid& actual, const DenseGrid& expected, const std::string& what) {
    ASSERT_EQ(actual.size(), expected.size()) << what;
    size_t mismatches = 0;
    for (int z = 0; z < expected.size().z; ++z)
        for (int y = 0; y < expected.size().y; ++y)
            for (int x = 0; x < expected.size().x; ++x) {
                const glm::ivec3 p(x, y, z);
                if (actual.at(p) != expected.at(p) && mismatches++ < 5)
                    ADD_FAILURE() << what << ": voxel (" << x << "," << y << "," << z << ") = " << actual.at(p)
                                  << ", expected " << expected.at(p);
            }
    EXPECT_EQ(mismatches, 0u) << what;
}

void expectNoValidationMessages(const VulkanContext& context) {
    for (const ValidationMessage& m : context.validationMessages())
        ADD_FAILURE() << (m.error ? "validation error: " : "validation warning: ") << m.text;
}

} // namespace

TEST(vulkan_Executor, StartKernelWritesThroughTheChunkTable) {
    for (const glm::ivec3 origin : kOrigins)
        for (const int32_t chunk : kChunkSizes) {
            const KernelPackage package = makePackage(makeWorld(kGridSize, origin, chunk), true, {});
            const RunResult result = runPackage(package);
            const std::string what = "chunk " + std::to_string(chunk) + " origin x " + std::to_string(origin.x);
            EXPECT_EQ(result.dispatches, 1u);
            const ChunkLayout& layout = result.grid.layout();
            EXPECT_EQ(layout.chunkSize, chunk);
            EXPECT_EQ(result.grid.data().size(), layout.chunkTotal() * layout.chunkVoxels());
            const DenseGrid dense = result.grid.toDense();
            expectEqualGrids(dense, referenceResult(package), what);
            // Padding outside the grid was cleared and never written: the buffer sums to the grid.
            double bufferSum = 0, gridSum = 0;
            for (float v : result.grid.data()) bufferSum += v;
            for (float v : dense.data()) gridSum += v;
            EXPECT_EQ(bufferSum, gridSum) << what;
        }
}

TEST(vulkan_Executor, GrammarMatchesThePlanOnEveryChunkSizeAndOrigin) {
    for (const glm::ivec3 origin : kOrigins) {
        std::optional<DenseGrid> first;
        for (const int32_t chunk : kChunkSizes) {
            const KernelPackage package = makePackage(makeWorld(kGridSize, origin, chunk), true, mixedGrammars());
            const RunResult result = runPackage(package);
            const std::string what = "chunk " + std::to_string(chunk) + " origin x " + std::to_string(origin.x);
            EXPECT_EQ(result.dispatches, countDispatches(package, {65535, 65535, 65535})) << what;
            const DenseGrid dense = result.grid.toDense();
            expectEqualGrids(dense, referenceResult(package), what);
            if (!first) first = dense;
            else EXPECT_EQ(dense.data(), first->data()) << what << " differs from chunk size 8";
        }
    }
}

TEST(vulkan_Executor, EachAnchorIsVisitedOncePerIteration) {
    // No start stage: the grid starts at 0, so each voxel counts how often it was an anchor.
    TestGrammar grammar;
    grammar.iterations = 4;
    grammar.stride = {2, 1, 3};
    grammar.boundsMin = {1, 2, 0};
    grammar.boundsMax = {30, 20, 17};
    grammar.sweeps = {{TestKernel::AddOne, {3, 2, 1}}};
    const World world = makeWorld({33, 22, 18}, {-37, -5, -100}, 16);
    const KernelPackage package = makePackage(world, false, {grammar});
    const DenseGrid dense = runPackage(package).grid.toDense();
    for (int z = 0; z < world.size.z; ++z)
        for (int y = 0; y < world.size.y; ++y)
            for (int x = 0; x < world.size.x; ++x) {
                // Anchors: boundsMin + n*stride with the [3,2,1] window inside the half-open bounds.
                const bool anchor = x >= 1 && (x - 1) % 2 == 0 && x + 3 <= 30 && y >= 2 && y + 2 <= 20 &&
                                    z % 3 == 0 && z + 1 <= 17;
                ASSERT_EQ(dense.at({x, y, z}), anchor ? 4.0f : 0.0f) << x << "," << y << "," << z;
            }
}

TEST(vulkan_Executor, StagingBatchingAndSplittingGiveTheSameResult) {
    const KernelPackage package = makePackage(makeWorld(kGridSize, {-37, -5, -100}, 16), true, mixedGrammars());
    const RunResult plain = runPackage(package);
    ExecutorOptions options;
    options.alwaysStage = true;
    options.dispatchesPerBatch = 3;
    options.maxWorkGroups = {1, 2, 3};
    const RunResult other = runPackage(package, options);
    EXPECT_GT(other.dispatches, plain.dispatches);
    EXPECT_EQ(other.grid.data(), plain.grid.data());
}

TEST(vulkan_Executor, TimedBatchesCallProgressOftenAndGiveTheSameResult) {
    // libvoxc sizes batches by time when a progress callback is set, so that Ctrl+C in Python
    // stops a run promptly: a target no batch can meet shrinks them to one dispatch each.
    std::vector<TestGrammar> grammars = mixedGrammars();
    grammars[0].iterations = 40; // some 500 dispatches
    const KernelPackage package = makePackage(makeWorld(kGridSize, {-37, -5, -100}, 16), true, grammars);
    int plainCalls = 0;
    ExecutorOptions plainOptions;
    plainOptions.progress = [&](double) { ++plainCalls; };
    const RunResult plain = runPackage(package, plainOptions);
    int timedCalls = 0;
    ExecutorOptions options;
    options.batchMilliseconds = 1e-9;
    options.progress = [&](double) { ++timedCalls; };
    const RunResult timed = runPackage(package, options);
    EXPECT_EQ(timed.grid.data(), plain.grid.data());
    EXPECT_EQ(timed.dispatches, plain.dispatches);
    ASSERT_GT(plain.dispatches, 256u);
    EXPECT_EQ(plainCalls, 1); // one batch of up to 4096 dispatches
    // 16, 16, 8, 4, 2, then one dispatch per batch.
    EXPECT_GT(uint64_t(timedCalls), plain.dispatches - 64);
}

TEST(vulkan_Executor, ValidationLayerReportsNothing) {
    ContextOptions contextOptions;
    contextOptions.validation = true;
    VulkanContext context(contextOptions);
    const KernelPackage package = makePackage(makeWorld(kGridSize, {100003, 7, -65541}, 8), true, mixedGrammars());
    const DenseGrid expected = referenceResult(package);
    for (const bool staged : {false, true}) {
        ExecutorOptions options;
        options.alwaysStage = staged;
        options.dispatchesPerBatch = 2; // several batches in flight, double-buffered
        options.maxWorkGroups = {2, 1, 4};
        VulkanExecutor executor(context, package, options);
        for (int run = 0; run < 2; ++run) expectEqualGrids(executor.run().grid.toDense(), expected, "validated run");
    }
    expectNoValidationMessages(context);
}

TEST(vulkan_Executor, ValidationLayerCatchesABadKernel) {
    // Positive control for the test above: a kernel reading push constants past the pipeline
    // layout's 112-byte range must be reported.
    ContextOptions contextOptions;
    contextOptions.validation = true;
    VulkanContext context(contextOptions);
    const KernelPackage package = makePackage(makeWorld({8, 8, 8}, {0, 0, 0}, 8), true, {}, TestKernel::OversizedPush);
    try {
        VulkanExecutor executor(context, package);
    } catch (const InternalError&) {
        // The driver may also reject it; the message must have been captured either way.
    }
    EXPECT_FALSE(context.validationMessages().empty());
}

TEST(vulkan_Executor, RepeatedRunsReuseThePipelines) {
    VulkanContext context;
    const KernelPackage package = makePackage(makeWorld(kGridSize, {0, 0, 0}, 32), true, mixedGrammars());
    VulkanExecutor executor(context, package);
    EXPECT_GT(executor.setupMs(), 0.0);
    const RunResult first = executor.run();
    const RunResult second = executor.run();
    EXPECT_EQ(first.grid.data(), second.grid.data());
    EXPECT_EQ(second.timings.setupMs, executor.setupMs());
    EXPECT_GT(second.timings.executeMs, 0.0);
    EXPECT_GE(second.timings.recordMs, 0.0);
    EXPECT_GE(second.timings.readbackMs, 0.0);
}

TEST(vulkan_Executor, FirstStageWritingEveryVoxelReplacesTheClear) {
    // Whole chunks and a start stage that writes every voxel: the buffer is not cleared, so the
    // second run starts on the first one's result, which the grammars changed, and must not see it.
    VulkanContext context;
    KernelPackage package = makePackage(makeWorld({48, 32, 32}, {0, 0, 0}, 16), true, mixedGrammars());
    package.stages.front().writesEveryDensity = true;
    VulkanExecutor executor(context, package);
    const RunResult first = executor.run();
    const RunResult second = executor.run();
    EXPECT_EQ(first.grid.data(), second.grid.data());
    expectEqualGrids(second.grid.toDense(), referenceResult(package), "second run");
}

TEST(vulkan_Executor, WithoutReadBackTheGridStaysOnTheDevice) {
    VulkanContext context;
    const KernelPackage package = makePackage(makeWorld(kGridSize, {0, 0, 0}, 16), true, mixedGrammars());
    VulkanExecutor onDevice(context, package, {.readBack = false});
    const RunResult result = onDevice.run();
    EXPECT_TRUE(result.grid.data().empty());
    EXPECT_EQ(result.grid.layout().gridSize, glm::ivec3(0));
    EXPECT_EQ(result.timings.readbackMs, 0.0);
    EXPECT_EQ(result.dispatches, countDispatches(package, {65535, 65535, 65535}));
    // The next run with a read-back still gets the whole result.
    expectEqualGrids(runPackage(package).grid.toDense(), referenceResult(package), "read back");
}

TEST(vulkan_Executor, SeedReachesTheKernels) {
    const KernelPackage package =
        makePackage(makeWorld({9, 9, 9}, {0, 0, 0}, 8, 0xABC12345u), true, {}, TestKernel::Seed);
    const DenseGrid dense = runPackage(package).grid.toDense();
    for (float v : dense.data()) ASSERT_EQ(v, float(0xABC));
}

TEST(vulkan_Executor, GridBeyondTheStorageBufferLimitIsUserError) {
    VulkanContext context;
    const KernelPackage package = makePackage(makeWorld({2048, 2048, 2048}, {0, 0, 0}, 64), true, {});
    try {
        VulkanExecutor executor(context, package);
        FAIL() << "a 32 GiB voxel buffer was accepted";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("run a box of the world with --region"), std::string::npos) << e.what();
    }
}

// A suite of its own, so ctest reports it skipped on a machine without a GPU.
TEST(vulkan_RealGpu, MatchesLavapipe) {
    bool gpu = false;
    for (const DeviceInfo& d : VulkanContext::listDevices()) gpu = gpu || (d.type != DeviceType::Cpu && d.hasCompute);
    if (!gpu) GTEST_SKIP() << "no GPU Vulkan device on this machine";
    const KernelPackage package = makePackage(makeWorld(kGridSize, {-37, -5, -100}, 16), true, mixedGrammars());
    const RunResult onGpu = runPackage(package, {}, ContextOptions{.device = "gpu"});
    const RunResult onCpu = runPackage(package, {}, ContextOptions{.device = "lavapipe"});
    EXPECT_EQ(onGpu.grid.data(), onCpu.grid.data());
}
