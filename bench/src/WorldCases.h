#pragma once
#include "JsonReporter.h"
#include "voxc/vulkan/Context.h"

namespace voxc::bench {

// world_tileT/N: `voxc world` of examples/scene.vox with its world enlarged to N x 64 x N, in
// tiles of T (world_tile64/256: 16 tiles, world_tile256/512: 4), each computed on the device
// with its halo (its kernels compiled: the compile cache is off), written as OpenVDB and meshed
// (.glb) into a fresh directory per iteration. Counters: tiles_per_second, voxels_per_second
// (voxels written) and halo_overhead (voxels computed over voxels written).
void registerWorldCases(JsonReporter& reporter, VulkanContext& context);

} // namespace voxc::bench
