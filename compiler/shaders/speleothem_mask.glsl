#version 450
// <<HEADER>>

// The first pass of a speleothem stage: every column's air voxels (density < 0.5) as bits, the
// grid before the stage that the second pass (speleothem_grow.glsl) finds its runs in, so no
// invocation reads a column another one is writing. One invocation per (x, z) column; the
// kernel is the same for every speleothem stage.

#include "common.glsl"
#include "speleothem_air.glsl"

// <<DISPATCH_SHAPE>>

void main() {
    ivec3 first = ivec3(gl_GlobalInvocationID) * ANCHORS_PER_INVOCATION;
    if (any(greaterThanEqual(first, push.anchorCount.xyz))) return;
    ivec3 last = min(first + ANCHORS_PER_INVOCATION, push.anchorCount.xyz);

    for (int z = first.z; z < last.z; ++z) {
        for (int x = first.x; x < last.x; ++x) {
            ivec3 columnLocal = push.anchorStart.xyz + ivec3(x, 0, z) * push.anchorStep.xyz;
            int firstWord = speleothemColumnWord(columnLocal.xz);
            uint bits = 0u;
            for (int y = 0; y < push.gridSize.y;) {
                ivec3 runStart = ivec3(columnLocal.x, y, columnLocal.z);
                int runEnd = columnRunEnd(runStart, y, push.gridSize.y);
                for (int address = voxelAddress(runStart); y < runEnd; ++y, address += push.gridOrigin.w) {
                    if (voxels.density[address] < 0.5) bits |= 1u << uint(y & 31);
                    if ((y & 31) == 31 || y == push.gridSize.y - 1) {
                        airMask.bits[firstWord + y / 32] = bits;
                        bits = 0u;
                    }
                }
            }
        }
    }
}
