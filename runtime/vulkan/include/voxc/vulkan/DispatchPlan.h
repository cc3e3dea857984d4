#pragma once
// Expands a KernelPackage's stage plans into the exact sequence of compute dispatches the
// executor records, one at a time, so a plan with many iterations never sits in memory
// as a list. Pure (no Vulkan), so the order and push constants are testable without a device.
#include "voxc/codegen/KernelPackage.h"

#include <array>
#include <cstdint>
#include <vector>

namespace voxc {

struct Dispatch {
    uint32_t kernel = 0;
    PushBlock push{};
    uint32_t groups[3] = {1, 1, 1}; // workgroups: ceil(anchorCount / (localSize * anchorsPerInvocation)) per axis
};

// Checks what the executor relies on (kernel indices, phase arrays of equal length, SPIR-V
// present, power-of-two chunk size); throws InternalError naming the problem, since a bad
// package is a compiler bug.
void validatePackage(const KernelPackage& package);

class DispatchCursor {
public:
    // `maxGroups`: the device's maxComputeWorkGroupCount; a phase needing more workgroups
    // along an axis is split into several dispatches over disjoint anchor ranges.
    DispatchCursor(const KernelPackage& package, std::array<uint32_t, 3> maxGroups);

    // Start stage: one dispatch of startKernel over the whole grid. Grammar stage: for each
    // iteration, each sweep (index in GrammarPlan::sweeps), each phase with anchors, in order.
    // Returns false when the plan is exhausted.
    bool next(Dispatch& out);

private:
    // Queues the dispatches of the next stage step (a start stage, or one grammar iteration).
    bool expandNextStep();
    void appendPhase(uint32_t kernel, int32_t iteration, int32_t sweep, glm::ivec3 start, glm::ivec3 step,
                     glm::ivec3 count);

    const KernelPackage& package_;
    std::array<uint32_t, 3> maxGroups_;
    PushBlock base_{};         // the fields every dispatch shares
    size_t stage_ = 0;         // next stage to expand
    uint32_t iteration_ = 0;   // next iteration of the current grammar stage
    std::vector<Dispatch> step_;
    size_t position_ = 0;
};

// Number of dispatches a package expands to (walks the whole plan).
uint64_t countDispatches(const KernelPackage& package, std::array<uint32_t, 3> maxGroups);

} // namespace voxc
