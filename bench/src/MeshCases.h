#pragma once
// The meshing cases: marching cubes and surface nets over the grids of examples/terrain.vox and
// examples/scene.vox resized to n^3 (generated once with Vulkan, outside the timing), on the
// host, on the Vulkan device, and OpenVDB's volumeToMesh as a peer.
#include "JsonReporter.h"
#include "voxc/vulkan/Context.h"

#include <vector>

namespace voxc::bench {

// Records "mesh_mc_<example>" (backends host, vulkan, openvdb), "mesh_sn_<example>" (host;
// there is no device surface nets) and "mesh_lod_<example>" (host: levels 0-2 by distance from
// the grid's (0, n/2, 0), transition cells between them), each with mvox_per_s, ms_per_32_chunk (the time over the
// grid's (n/32)^3 chunks) and triangles; with host also "edit_remesh" (n = brush radius 4, 8, 16 on
// scene.vox at 256^3: ms from a brush to its re-meshed chunks).
void registerMeshCases(JsonReporter& reporter, VulkanContext& context, const std::vector<int>& sizes, bool host,
                       bool vulkan, bool openvdb);

} // namespace voxc::bench
