#version 450
// <<HEADER>>

// The start state: every grid voxel gets the start block's shapes in order over air
// (density 0, material none), as voxc::startVoxel does on the CPU. One invocation owns a
// column of voxels along y, so per-column values (a heightfield's height) are computed once,
// and the chunk table is consulted once per chunk the column enters instead of once per voxel.

#include "common.glsl"
#include "random.glsl"
#include "perlin.glsl"

// <<DISPATCH_SHAPE>>

void main() {
    ivec3 first = ivec3(gl_GlobalInvocationID) * ANCHORS_PER_INVOCATION;
    if (any(greaterThanEqual(first, push.anchorCount.xyz))) return;
    ivec3 last = min(first + ANCHORS_PER_INVOCATION, push.anchorCount.xyz);
    uint seed = uint(push.gridSize.w);

    for (int z = first.z; z < last.z; ++z) {
        for (int x = first.x; x < last.x; ++x) {
            ivec3 columnLocal = push.anchorStart.xyz + ivec3(x, first.y, z) * push.anchorStep.xyz;
            ivec3 world = push.gridOrigin.xyz + columnLocal;
            // <<COLUMN_VALUES>>
            for (int y = first.y; y < last.y;) {
                ivec3 runStart = push.anchorStart.xyz + ivec3(x, y, z) * push.anchorStep.xyz;
                int runEnd = columnRunEnd(runStart, y, last.y);
                for (int address = voxelAddress(runStart); y < runEnd; ++y, address += push.gridOrigin.w) {
                    ivec3 local = push.anchorStart.xyz + ivec3(x, y, z) * push.anchorStep.xyz;
                    world = push.gridOrigin.xyz + local;
                    float density = 0.0;
                    uint material = 0u;
                    // <<SHAPES>>
                    voxels.density[address] = density;
                }
            }
        }
    }
}
