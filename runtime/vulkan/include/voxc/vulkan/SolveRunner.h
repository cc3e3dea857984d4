#pragma once
// Runs a SolveProgram (voxc/codegen/KernelPackage.h), the dispatch shape of a global solve: its
// storage buffers on the device, the prologue, then cycles until the convergence measure is at
// or below the tolerance or the cycle cap is reached. Kind-free: the curves' multigrid
// (GpuMultigrid.h) is one program; any iterative schedule over dense buffers is another.
#include "voxc/codegen/KernelPackage.h"
#include "voxc/vulkan/Context.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace voxc {

struct SolveRun {
    std::vector<float> measures;                // after the prologue, then after each cycle (a count as a float)
    std::vector<std::vector<uint32_t>> buffers; // the first `readWords[b]` words of each buffer b
    double executeMs = 0;                       // first submit -> last fence
    uint64_t dispatches = 0;
    bool converged = false;                     // the last measure is <= the tolerance (a count: 0)
};

class VulkanSolveRunner {
public:
    // Builds the program's pipelines (InternalError when the driver rejects one); `context` must
    // outlive the runner.
    VulkanSolveRunner(VulkanContext& context, const SolveProgram& program);
    ~VulkanSolveRunner();
    VulkanSolveRunner(const VulkanSolveRunner&) = delete;
    VulkanSolveRunner& operator=(const VulkanSolveRunner&) = delete;

    // Buffers start as `initial[b]` (zero past its end; all zero when absent); a UserError when
    // a buffer exceeds what the device binds. Stops after the cycle whose measure is <= the
    // tolerance (a count: is 0), or after maxCycles (then SolveRun::converged is false: the caller reports it).
    SolveRun run(const std::vector<std::vector<uint32_t>>& initial, const std::vector<uint64_t>& readWords);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace voxc
