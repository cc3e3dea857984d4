#pragma once
#include "JsonReporter.h"

#include "voxc/vulkan/Context.h"

namespace voxc::bench {

// Registers view_frame: milliseconds per 1280x720 offscreen frame of examples/scene.vox's mesh
// (MeshRenderer: draw, wait, read the picture back), after a warm-up frame; record n = 720, the
// picture's height. Issue 13's goal: at least 30 frames per second on lavapipe.
void registerViewFrame(JsonReporter& reporter, VulkanContext& context);

} // namespace voxc::bench
