#pragma once
#include "JsonReporter.h"

#include "voxc/vulkan/Context.h"

namespace voxc::bench {

// Registers curves at 128x64x128 (record n = 128): examples/curves_cliff.vox at twice its size.
// curves/host_solve times checking the file, which runs the whole solve on the host (the Vulkan
// solve does not exist yet); curves/vulkan and curves/interp time a run of the pipeline (the
// start state and the stage combining the solved table). `context` is null when Vulkan is not benched;
// `host` registers the solve.
void registerCurves(JsonReporter& reporter, VulkanContext* context, bool interp, bool host);

} // namespace voxc::bench
