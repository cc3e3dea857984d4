#pragma once
// The terrain's pipe-model erosion steps (terrain::erosionStep, docs/terrain.md "Erosion") as a
// SolveProgram run on a Vulkan device: the same passes in the same operation order
// (compiler/shaders/erosion_*.glsl), so lavapipe gives the host's channels bit for bit. The
// schedule across levels (prolongation, the Gaussians, the final deposit) stays on the host and
// calls this for each level's run of steps (terrain::ErosionSettings::runner).
#include "voxc/codegen/KernelPackage.h"
#include "voxc/generators/terrain/Terrain.h"
#include "voxc/vulkan/Context.h"

namespace voxc {

// The program for `steps` steps numbered firstStep.. on a width x height level (drain: the drain's
// steps, no rain): buffer 0 holds 16 words of constants, then the grid's channels one after
// another (GpuErosion.cpp, kChannel*); buffer 1 the runner's measure word, unused.
SolveProgram erosionProgram(int32_t width, int32_t height, const terrain::ErosionParams& params, int32_t level,
                            uint32_t firstStep, uint32_t steps, bool drain);

// A terrain::ErosionRunner running erosionProgram on `context` (which must outlive it): the grid
// is uploaded, stepped on the device and read back, every channel as the host loop leaves it.
terrain::ErosionRunner vulkanErosionRunner(VulkanContext& context);

} // namespace voxc
