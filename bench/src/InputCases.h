#pragma once
#include "JsonReporter.h"

#include "voxc/program/Program.h"

namespace voxc::bench {

// heightmap/512: a 4096^2 float32 .npy map (a smooth analytic relief, written to a temporary
// directory that is gone when this returns) read by a heightmap block and sampled once per column
// of a 512x128x512 grid as the ground.
Program heightmapProgram();

// Registers mesh_sdf/256/host: OpenVDB's meshToVolume (through voxc::inputs::meshDistances) of a
// 99,904-triangle sphere of radius 110 into a band of 3 voxels, in a 256^3 box.
void registerMeshSdf(JsonReporter& reporter);

} // namespace voxc::bench
