#include "TestKernels.h"
#include "voxc/core/Errors.h"
#include "voxc/vulkan/DispatchPlan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

using namespace voxc;
using namespace voxc::test;

namespace {

constexpr std::array<uint32_t, 3> kNoLimit{65535, 65535, 65535};

std::vector<Dispatch> expand(const KernelPackage& package, std::array<uint32_t, 3> maxGroups = kNoLimit) {
    DispatchCursor cursor(package, maxGroups);
    std::vector<Dispatch> all;
    Dispatch d;
    while (cursor.next(d)) all.push_back(d);
    return all;
}

glm::ivec3 xyz(const int32_t (&v)[4]) { return {v[0], v[1], v[2]}; }

// Every anchor of a dispatch, as (kernel, iteration, sweep, anchor) -> times covered.
using Visits = std::map<std::tuple<uint32_t, int, int, int, int, int>, int>;
void visit(const Dispatch& d, Visits& visits) {
    const glm::ivec3 start = xyz(d.push.anchorStart), step = xyz(d.push.anchorStep), count = xyz(d.push.anchorCount);
    for (int z = 0; z < count.z; ++z)
        for (int y = 0; y < count.y; ++y)
            for (int x = 0; x < count.x; ++x) {
                const glm::ivec3 a = start + glm::ivec3(x, y, z) * step;
                ++visits[{d.kernel, d.push.chunkBase[3], d.push.chunkCount[3], a.x, a.y, a.z}];
            }
}

} // namespace

TEST(vulkan_DispatchPlan, StartThenIterationsSweepsPhasesInOrder) {
    const World world = makeWorld({20, 12, 9}, {-37, -5, -100}, 8, 0xDEADBEEFu);
    TestGrammar grammar;
    grammar.iterations = 3;
    grammar.sweeps = {{TestKernel::AddOne, {1, 2, 1}}, {TestKernel::Shift, {2, 1, 1}}};
    const KernelPackage package = makePackage(world, true, {grammar});
    const std::vector<Dispatch> dispatches = expand(package);

    // Start: the whole grid once; then per iteration both sweeps (equal volumes: declaration order), 2 phases each.
    ASSERT_EQ(dispatches.size(), 1u + 3u * (2u + 2u));
    const Dispatch& start = dispatches[0];
    EXPECT_EQ(start.kernel, package.stages[0].gridKernel);
    EXPECT_EQ(xyz(start.push.anchorStart), glm::ivec3(0));
    EXPECT_EQ(xyz(start.push.anchorStep), glm::ivec3(1));
    EXPECT_EQ(xyz(start.push.anchorCount), world.size);
    EXPECT_EQ(start.groups[0], 3u); // ceil(20 / 8)
    EXPECT_EQ(start.groups[1], 2u); // ceil(12 / 8)
    EXPECT_EQ(start.groups[2], 9u);

    const ChunkLayout layout = ChunkLayout::make(world.origin, world.size, world.chunkSize);
    const GrammarPlan& plan = package.stages[1].grammar.value();
    size_t i = 1;
    for (int it = 0; it < 3; ++it)
        for (int s = 0; s < 2; ++s)
            for (int p = 0; p < 2; ++p, ++i) {
                const Dispatch& d = dispatches[i];
                const SweepPlan& sweep = plan.sweeps[s];
                EXPECT_EQ(d.kernel, sweep.kernel);
                EXPECT_EQ(xyz(d.push.gridOrigin), world.origin);
                EXPECT_EQ(d.push.gridOrigin[3], 8);
                EXPECT_EQ(xyz(d.push.gridSize), world.size);
                EXPECT_EQ(uint32_t(d.push.gridSize[3]), 0xDEADBEEFu);
                EXPECT_EQ(xyz(d.push.chunkBase), layout.chunkBase);
                EXPECT_EQ(d.push.chunkBase[3], it);
                EXPECT_EQ(xyz(d.push.chunkCount), layout.chunkCount);
                EXPECT_EQ(d.push.chunkCount[3], s);
                EXPECT_EQ(xyz(d.push.anchorStart), sweep.phaseStart[p]);
                EXPECT_EQ(xyz(d.push.anchorStep), sweep.phaseStep[p]);
                EXPECT_EQ(xyz(d.push.anchorCount), sweep.phaseCount3[p]);
            }
    EXPECT_EQ(countDispatches(package, kNoLimit), dispatches.size());
}

TEST(vulkan_DispatchPlan, PhasesWithoutAnchorsAreSkipped) {
    // Window 3 with stride 1 over a 4-voxel span: 2 anchors, so phase residue 2 has none.
    TestGrammar grammar;
    grammar.sweeps = {{TestKernel::AddOne, {3, 1, 1}}};
    grammar.boundsMax = {4, 5, 5};
    const KernelPackage package = makePackage(makeWorld({5, 5, 5}, {0, 0, 0}, 8), false, {grammar});
    ASSERT_EQ(package.stages[0].grammar->sweeps[0].phaseStart.size(), 3u);
    const std::vector<Dispatch> dispatches = expand(package);
    ASSERT_EQ(dispatches.size(), 2u);
    for (const Dispatch& d : dispatches) EXPECT_EQ(d.push.anchorCount[0], 1);
}

TEST(vulkan_DispatchPlan, SplitsDispatchesAboveTheWorkgroupLimit) {
    TestGrammar grammar;
    grammar.iterations = 2;
    grammar.stride = {1, 2, 1};
    grammar.sweeps = {{TestKernel::AddOne, {2, 3, 2}}};
    const KernelPackage package = makePackage(makeWorld({45, 40, 13}, {3, -9, 1}, 16), true, {grammar});
    const std::vector<Dispatch> whole = expand(package);
    const std::array<uint32_t, 3> limit{2, 1, 3};
    const std::vector<Dispatch> split = expand(package, limit);
    EXPECT_GT(split.size(), whole.size());
    Visits wholeVisits, splitVisits;
    for (const Dispatch& d : whole) visit(d, wholeVisits);
    for (const Dispatch& d : split) {
        for (int a = 0; a < 3; ++a) EXPECT_LE(d.groups[a], limit[a]);
        visit(d, splitVisits);
    }
    EXPECT_EQ(splitVisits, wholeVisits);
    for (const auto& [anchor, times] : wholeVisits) EXPECT_EQ(times, 1);
}

TEST(vulkan_DispatchPlan, WorkgroupsCoverAnchorsPerInvocation) {
    // The start kernel walks columns: 4 anchors per invocation along y, local size 8 x 1 x 8.
    const World world = makeWorld({20, 12, 9}, {0, 0, 0}, 8);
    KernelPackage package = makePackage(world, true, {});
    Kernel& start = package.kernels[package.stages[0].gridKernel];
    const uint32_t local[3] = {8, 1, 8}, perInvocation[3] = {1, 4, 1};
    std::copy(local, local + 3, start.localSize);
    std::copy(perInvocation, perInvocation + 3, start.anchorsPerInvocation);
    const std::vector<Dispatch> whole = expand(package);
    ASSERT_EQ(whole.size(), 1u);
    EXPECT_EQ(whole[0].groups[0], 3u); // ceil(20 / 8)
    EXPECT_EQ(whole[0].groups[1], 3u); // ceil(12 / (1 * 4))
    EXPECT_EQ(whole[0].groups[2], 2u); // ceil(9 / 8)
    EXPECT_EQ(xyz(whole[0].push.anchorCount), world.size);

    // Split by the workgroup limit, the pieces still cover every voxel once.
    const std::array<uint32_t, 3> limit{1, 2, 1};
    Visits visits;
    for (const Dispatch& d : expand(package, limit)) {
        for (int a = 0; a < 3; ++a) EXPECT_LE(d.groups[a], limit[a]);
        visit(d, visits);
    }
    EXPECT_EQ(visits.size(), size_t(20 * 12 * 9));
    for (const auto& [voxel, times] : visits) EXPECT_EQ(times, 1);
}

TEST(vulkan_DispatchPlan, MalformedPackagesAreInternalErrors) {
    TestGrammar grammar;
    grammar.sweeps = {{TestKernel::AddOne, {1, 1, 1}}};
    const KernelPackage good = makePackage(makeWorld({8, 8, 8}, {0, 0, 0}, 8), true, {grammar});
    EXPECT_NO_THROW(validatePackage(good));

    KernelPackage badIndex = good;
    badIndex.stages[1].grammar->sweeps[0].kernel = 7;
    EXPECT_THROW(validatePackage(badIndex), InternalError);

    KernelPackage ragged = good;
    ragged.stages[1].grammar->sweeps[0].phaseStep.clear();
    EXPECT_THROW(validatePackage(ragged), InternalError);

    KernelPackage noSpirv = good;
    noSpirv.kernels[0].spirv.clear();
    EXPECT_THROW(validatePackage(noSpirv), InternalError);

    KernelPackage noAnchors = good;
    noAnchors.kernels[0].anchorsPerInvocation[1] = 0;
    EXPECT_THROW(validatePackage(noAnchors), InternalError);

    KernelPackage oddChunk = good;
    oddChunk.world.chunkSize = 12;
    EXPECT_THROW(validatePackage(oddChunk), InternalError);
}

TEST(vulkan_DispatchPlan, FieldStagesCoverTheGridThenInvalidateTileRanges) {
    const World world = makeWorld({20, 12, 9}, {-37, -5, -100}, 8);
    KernelPackage package = makePackage(world, true, {});
    StagePlan field;
    field.kind = "field";
    field.label = "union f";
    field.gridKernel = package.stages[0].gridKernel;
    package.stages.push_back(field);
    validatePackage(package);
    DispatchCursor cursor(package, kNoLimit, 3);
    std::vector<Dispatch> all;
    Dispatch d;
    while (cursor.next(d)) all.push_back(d);
    // start, invalidate, field, invalidate: a field rewrites densities, so every tile range is stale.
    ASSERT_EQ(all.size(), 4u);
    EXPECT_EQ(all[2].kind, DispatchKind::Direct);
    EXPECT_EQ(all[2].kernel, field.gridKernel);
    EXPECT_EQ(xyz(all[2].push.anchorStart), glm::ivec3(0));
    EXPECT_EQ(xyz(all[2].push.anchorCount), world.size);
    EXPECT_EQ(all[3].kind, DispatchKind::InvalidateRanges);
}

TEST(vulkan_DispatchPlan, FieldBoxesDispatchOneByOneAndCarryTheirConstant) {
    const World world = makeWorld({20, 12, 9}, {-37, -5, -100}, 8);
    KernelPackage package = makePackage(world, true, {});
    StagePlan field;
    field.kind = "field";
    field.label = "set f";
    field.gridKernel = package.stages[0].gridKernel;
    field.gridBoxes = {FieldBox{{0, 0, 0}, {20, 12, 4}, false, 0.0f}, FieldBox{{0, 0, 4}, {20, 12, 9}, true, -0.0f}};
    package.stages.push_back(field);
    validatePackage(package);
    DispatchCursor cursor(package, kNoLimit);
    std::vector<Dispatch> all;
    Dispatch d;
    while (cursor.next(d)) all.push_back(d);
    ASSERT_EQ(all.size(), 3u); // start, then one dispatch per box
    EXPECT_EQ(xyz(all[1].push.anchorStart), glm::ivec3(0));
    EXPECT_EQ(xyz(all[1].push.anchorCount), glm::ivec3(20, 12, 4));
    EXPECT_EQ(all[1].push.anchorCount[3], 0);
    EXPECT_EQ(xyz(all[2].push.anchorStart), glm::ivec3(0, 0, 4));
    EXPECT_EQ(xyz(all[2].push.anchorCount), glm::ivec3(20, 12, 5));
    EXPECT_EQ(all[2].push.anchorCount[3], 1);
    EXPECT_EQ(uint32_t(all[2].push.anchorStart[3]), 0x80000000u); // -0.0's bits: the sign survives

    KernelPackage skipped = package;
    skipped.stages.back().gridBoxes.back().unchanged = true;
    DispatchCursor skippedCursor(skipped, kNoLimit);
    size_t dispatches = 0;
    while (skippedCursor.next(d)) ++dispatches;
    EXPECT_EQ(dispatches, 2u); // the unchanged box is not dispatched

    KernelPackage gap = package;
    gap.stages.back().gridBoxes.pop_back();
    EXPECT_THROW(validatePackage(gap), InternalError);
}

// The executor copies a stage's non-finite counts out where the stage's dispatches end, so every
// dispatch names its stage, and the stages come in plan order (InvalidateRanges included).
TEST(vulkan_DispatchPlan, EveryDispatchNamesItsStageInPlanOrder) {
    const World world = makeWorld({20, 12, 9}, {-37, -5, -100}, 8);
    TestGrammar grammar;
    grammar.iterations = 2;
    grammar.sweeps = {{TestKernel::AddOne, {1, 2, 1}}};
    KernelPackage package = makePackage(world, true, {grammar});
    StagePlan field;
    field.kind = "field";
    field.gridKernel = package.stages[0].gridKernel;
    package.stages.push_back(field);
    validatePackage(package);
    for (int32_t tileShift : {-1, 3}) {
        DispatchCursor cursor(package, kNoLimit, tileShift);
        std::vector<uint32_t> stages;
        Dispatch d;
        while (cursor.next(d)) stages.push_back(d.stage);
        ASSERT_FALSE(stages.empty());
        EXPECT_TRUE(std::is_sorted(stages.begin(), stages.end()));
        // start, grammar, field: each has dispatches of its own, except that the test grammar has no
        // active-tiles kernel, so skipping tiles leaves its sweep out.
        const std::set<uint32_t> expected = tileShift < 0 ? std::set<uint32_t>{0, 1, 2} : std::set<uint32_t>{0, 2};
        EXPECT_EQ(std::set<uint32_t>(stages.begin(), stages.end()), expected);
    }
}
