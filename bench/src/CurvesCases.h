#pragma once
#include "JsonReporter.h"

#include "voxc/vulkan/Context.h"

namespace voxc::bench {

// Registers curves at 128x64x128 and 256x128x256 (records n = 128, 256): examples/curves_cliff.vox
// at twice and four times its size. curves/host_solve/N and curves/vulkan_solve/N (case
// curves_solve) time checking the file, which solves the block: all on the host, or with the
// multigrid on the device; the parts' times are counters. curves/vulkan/N and curves/interp/N time
// a run of the pipeline (the start state and the stage combining the solved table). `context` is
// null when Vulkan is not benched; `host` registers the host solve.
void registerCurves(JsonReporter& reporter, VulkanContext* context, bool interp, bool host);

} // namespace voxc::bench
