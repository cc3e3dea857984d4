#version 450
// <<HEADER>>

// A field stage: every grid voxel's density d is combined with the field's value f there.
// One invocation owns a column of voxels along y, like the start kernel, so the nodes that do
// not depend on y are computed once per column; the rest are straight-line code per voxel,
// every float result `precise`, in the interpreter's operation order (voxc::FieldEvaluator).
// The runtime dispatches it per box of chunks (KernelPackage StagePlan::fieldBoxes); in a box
// where interval analysis proved the field one exact float (anchorCount.w == 1, the float's
// bits in anchorStart.w) only the combine runs, in a loop of its own so no DAG code is near it.
// Where the field's value is not finite the combine uses 0 instead (fieldDensity, counted);
// a constant box's value is finite (interval analysis proves no NaN or infinity exact).
// Noise calls the column shares work for (noise_column.glsl) fill noiseColumnValues a block of
// COLUMN_BLOCK voxels at a time, before the voxels of the block read them; point-set lookups along
// the column (point_set_column.glsl) fill pointSetColumnValues the same way.

#include "common.glsl"
#include "nonfinite.glsl"
#include "opaque_constants.glsl"

// <<COLUMN_BLOCK>>

// The invocation's non-finite values, added to the stage's count once at the end of main
// (flushNonFiniteTally) rather than by finiteDensity's atomics at each voxel: the same count and
// lowest index. Why: llvmpipe runs an atomic as a loop over the lanes even when no lane takes the
// branch, so three such loops per voxel were a twentieth of a noise field's kernel.
uint nonFiniteTally = 0u;
uint nonFiniteTallyFirst = 0xFFFFFFFFu;

// `value` when finite; otherwise 0, tallied at grid-local voxel `local`.
float fieldDensity(float value, ivec3 local) {
    if (isFiniteFloat(value)) return value;
    nonFiniteTally += 1u;
    nonFiniteTallyFirst = min(nonFiniteTallyFirst, uint(local.x + push.gridSize.x * (local.y + push.gridSize.y * local.z)));
    return 0.0;
}

// The tally into the stage's 64-bit count (a carry out of countLow goes to countHigh) and lowest index.
void flushNonFiniteTally() {
    if (nonFiniteTally == 0u) return;
    if (atomicAdd(nonFinite.countLow, nonFiniteTally) > 0xFFFFFFFFu - nonFiniteTally) atomicAdd(nonFinite.countHigh, 1u);
    atomicMin(nonFinite.firstIndex, nonFiniteTallyFirst);
}
// <<COLUMN_NOISE>>
// <<COLUMN_POINT_SETS>>
// <<LIBRARIES>>

// <<DISPATCH_SHAPE>>

void main() {
    ivec3 first = ivec3(gl_GlobalInvocationID) * ANCHORS_PER_INVOCATION;
    if (any(greaterThanEqual(first, push.anchorCount.xyz))) return;
    ivec3 last = min(first + ANCHORS_PER_INVOCATION, push.anchorCount.xyz);

    if (push.anchorCount.w == 1) {
        float constantValue = intBitsToFloat(push.anchorStart.w);
        for (int z = first.z; z < last.z; ++z) {
            for (int x = first.x; x < last.x; ++x) {
                for (int y = first.y; y < last.y;) {
                    ivec3 runStart = push.anchorStart.xyz + ivec3(x, y, z) * push.anchorStep.xyz;
                    int runEnd = columnRunEnd(runStart, y, last.y);
                    for (int address = voxelAddress(runStart); y < runEnd; ++y, address += push.gridOrigin.w) {
                        ivec3 local = push.anchorStart.xyz + ivec3(x, y, z) * push.anchorStep.xyz;
                        // <<CONSTANT_COMBINE>>
                    }
                }
            }
        }
        return;
    }

    for (int z = first.z; z < last.z; ++z) {
        for (int x = first.x; x < last.x; ++x) {
            ivec3 columnLocal = push.anchorStart.xyz + ivec3(x, first.y, z) * push.anchorStep.xyz;
            // Integer sum first, then one conversion, as the interpreter does.
            ivec3 columnWorld = push.gridOrigin.xyz + columnLocal;
            // <<COLUMN_VALUES>>
            for (int blockY = first.y; blockY < last.y; blockY += COLUMN_BLOCK) {
                int blockEnd = min(blockY + COLUMN_BLOCK, last.y);
                // <<BLOCK_VALUES>>
                for (int y = blockY; y < blockEnd;) {
                    ivec3 runStart = push.anchorStart.xyz + ivec3(x, y, z) * push.anchorStep.xyz;
                    int runEnd = columnRunEnd(runStart, y, blockEnd);
                    for (int address = voxelAddress(runStart); y < runEnd; ++y, address += push.gridOrigin.w) {
                        ivec3 local = push.anchorStart.xyz + ivec3(x, y, z) * push.anchorStep.xyz;
                        ivec3 world = push.gridOrigin.xyz + local;
                        // <<VOXEL_VALUES>>
                        // <<COMBINE>>
                    }
                }
            }
        }
    }
    flushNonFiniteTally();
}
