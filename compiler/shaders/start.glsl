#version 450
// <<HEADER>>

// The start state: one invocation per grid voxel evaluates the start block's shapes in
// order over air (density 0), as voxc::startDensity does on the CPU.

#include "common.glsl"
#include "random.glsl"
#include "perlin.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(id, push.anchorCount.xyz))) return;
    ivec3 local = push.anchorStart.xyz + id * push.anchorStep.xyz;
    ivec3 world = push.gridOrigin.xyz + local;
    uint seed = uint(push.gridSize.w);

    float density = 0.0;
    // <<SHAPES>>
    voxels.density[voxelAddress(local)] = density;
}
