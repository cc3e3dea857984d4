#version 450
// <<HEADER>>

// The stamp pass of one sweep (docs/language.md, "Stamps"), run after each phase's sweep kernel,
// which recorded the rule each anchor fired (firedRule). One invocation per voxel that the
// phase's windows, grown by the sweep's reach, cover: it folds the stamps of every firing whose
// grown window holds it, in anchor order (z, then y, then x), each as voxc::combineField, as the
// interpreter applies them one firing after another. No two invocations share a voxel, so the
// result does not depend on the dispatch or the chunk size.
// Push block: the voxels are anchorStart.xyz + id, id < anchorCount.xyz; anchorStep.xyz is the
// phase's first anchor.

#include "common.glsl"
#include "nonfinite.glsl"
// <<LIBRARIES>>

// <<DISPATCH_SHAPE>>

// <<SWEEP_CONSTANTS>>

ivec3 floorDivide(ivec3 a, ivec3 b) {
    return ivec3(a.x >= 0 ? a.x / b.x : -((-a.x + b.x - 1) / b.x), a.y >= 0 ? a.y / b.y : -((-a.y + b.y - 1) / b.y),
                 a.z >= 0 ? a.z / b.z : -((-a.z + b.z - 1) / b.z));
}

void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(id, push.anchorCount.xyz))) return;
    ivec3 local = push.anchorStart.xyz + id;
    ivec3 world = push.gridOrigin.xyz + local;
    ivec3 phaseStart = push.anchorStep.xyz;
    // The anchors phaseStart + i * PHASE_STEP (up to LAST_ANCHOR) whose grown window holds the
    // voxel: anchor - REACH <= local < anchor + WINDOW + REACH.
    ivec3 first = max(-floorDivide(phaseStart - (local - WINDOW - REACH + 1), PHASE_STEP), ivec3(0));
    ivec3 last = floorDivide(min(local + REACH, LAST_ANCHOR) - phaseStart, PHASE_STEP);
    int address = voxelAddress(local);
    for (int k = first.z; k <= last.z; ++k) {
        for (int j = first.y; j <= last.y; ++j) {
            for (int i = first.x; i <= last.x; ++i) {
                ivec3 anchor = phaseStart + ivec3(i, j, k) * PHASE_STEP;
                uint fired = firedRule.rule[firedIndex(anchor)];
                if (fired == 0u) continue;
                ivec3 fromAnchor = local - anchor;
                // <<STAMPS>>
            }
        }
    }
}
