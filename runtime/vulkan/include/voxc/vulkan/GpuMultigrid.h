#pragma once
// The curves' linear solves (curves::solveLaplace: geometric multigrid, FMG then V(3,3) cycles,
// red-black Gauss-Seidel) as a SolveProgram run on a Vulkan device: the same schedule in the same
// operation order (compiler/shaders/mg_*.glsl), so lavapipe gives the host's values bit for bit.
// Its own library (voxc_gpu_solve), as the GPU mesher: it compiles its passes with glslang.
#include "voxc/codegen/KernelPackage.h"
#include "voxc/generators/curves/Multigrid.h"
#include "voxc/vulkan/Context.h"

namespace voxc {

// The program for `components` (1 to 3) unknowns per cell on the hierarchy `levels`
// (curves::multigridLevels): buffers 0 the Dirichlet mask, 1 the unknowns u, 2 the right-hand
// sides f (levels one after another, finest first; a cell's components side by side), 3 the max
// residual's bits.
SolveProgram multigridProgram(const std::vector<curves::MultigridLevel>& levels, int32_t components, float tolerance,
                              int32_t maxCycles);

// A curves::LinearSolver running multigridProgram on `context` (which must outlive it); throws
// ConvergenceError past the cycle cap, as the host does.
curves::LinearSolver vulkanLinearSolver(VulkanContext& context);

} // namespace voxc
