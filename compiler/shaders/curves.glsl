#version 450
// <<HEADER>>

// A curves stage: the host-solved density of its box (a solve table) combined with every grid
// voxel of the box by the stage's mode, as voxc::combineField does, with the table's material
// where the table wins and the result is solid. The runtime dispatches it over the solve box
// only (StagePlan::gridBoxes); one invocation owns a column along y, like a field kernel.

#include "common.glsl"
#include "solve_tables.glsl"

// <<DISPATCH_SHAPE>>

// <<TABLE>>

void main() {
    ivec3 first = ivec3(gl_GlobalInvocationID) * ANCHORS_PER_INVOCATION;
    if (any(greaterThanEqual(first, push.anchorCount.xyz))) return;
    ivec3 last = min(first + ANCHORS_PER_INVOCATION, push.anchorCount.xyz);
    int start = solveTableStart(SOLVE_TABLE);
    ivec3 tableMin = solveTableMin(start);
    ivec3 tableSize = solveTableSize(start);
    int densities = start + 6;
    int materialsAt = densities + tableSize.x * tableSize.y * tableSize.z;

    for (int z = first.z; z < last.z; ++z) {
        for (int x = first.x; x < last.x; ++x) {
            for (int y = first.y; y < last.y;) {
                ivec3 runStart = push.anchorStart.xyz + ivec3(x, y, z) * push.anchorStep.xyz;
                int runEnd = columnRunEnd(runStart, y, last.y);
                for (int address = voxelAddress(runStart); y < runEnd; ++y, address += push.gridOrigin.w) {
                    ivec3 local = push.anchorStart.xyz + ivec3(x, y, z) * push.anchorStep.xyz;
                    ivec3 cell = local - tableMin;
                    int at = cell.x + tableSize.x * (cell.y + tableSize.y * cell.z);
                    float f = intBitsToFloat(solveTables.words[densities + at]);
                    // <<COMBINE>>
                }
            }
        }
    }
}
