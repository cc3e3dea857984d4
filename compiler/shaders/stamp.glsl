#version 450
// <<HEADER>>

// The stamp pass of one sweep (docs/language.md, "Stamps"), run after each phase's sweep kernel,
// which recorded the rule each anchor fired (firedRule) and set the firing bits of the anchors
// that fired a rule with stamps. One invocation per voxel that the phase's windows, grown by the
// sweep's reach, cover: it folds the stamps of every firing whose grown window holds it, in anchor
// order (z, then y, then x), each as voxc::combineField, as the interpreter applies them one
// firing after another. It reads a word of bits per 32 anchors along x and visits the set ones
// alone, so a voxel pays for the firings near it, not for every anchor that could reach it. No two
// invocations share a voxel, so the result does not depend on the dispatch or the chunk size.
// Push block: the voxels are anchorStart.xyz + id, id < anchorCount.xyz; anchorStep.xyz is the
// phase's first anchor.

#include "common.glsl"
#include "nonfinite.glsl"
#include "opaque_constants.glsl"
// <<LIBRARIES>>

// <<DISPATCH_SHAPE>>

// <<SWEEP_CONSTANTS>>

ivec3 floorDivide(ivec3 a, ivec3 b) {
    return ivec3(a.x >= 0 ? a.x / b.x : -((-a.x + b.x - 1) / b.x), a.y >= 0 ? a.y / b.y : -((-a.y + b.y - 1) / b.y),
                 a.z >= 0 ? a.z / b.z : -((-a.z + b.z - 1) / b.z));
}

// The written window's cell of a voxel fromAnchor cells from a variant's anchor, as
// voxc::stampLocal: the variant's axis `axis` reads written axis from[axis], mirrored in the
// written window (size) where negate[axis].
ivec3 stampWrittenCell(ivec3 fromAnchor, ivec3 from, bvec3 negate, ivec3 size) {
    ivec3 written;
    written[from.x] = negate.x ? size[from.x] - 1 - fromAnchor.x : fromAnchor.x;
    written[from.y] = negate.y ? size[from.y] - 1 - fromAnchor.y : fromAnchor.y;
    written[from.z] = negate.z ? size[from.z] - 1 - fromAnchor.z : fromAnchor.z;
    return written;
}

// A stamp's reach along the variant's axes from the written rule's (Stamp::reach).
ivec3 stampVariantReach(ivec3 writtenReach, ivec3 from) {
    return ivec3(writtenReach[from.x], writtenReach[from.y], writtenReach[from.z]);
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
    // The firing bits of anchor i (relative to phaseStart) are at phase lattice base + i.
    ivec3 base = phaseLattice(phaseStart);
    int fromBit = base.x + first.x, toBit = base.x + last.x;
    for (int k = first.z; k <= last.z; ++k) {
        for (int j = first.y; j <= last.y; ++j) {
            int row = firingRow(base + ivec3(0, j, k));
            for (int w = fromBit >> 5; w <= toBit >> 5; ++w) {
                // Bits fromBit .. toBit of the row that lie in word w.
                uint bits = firedRule.rule[row + w] & (0xffffffffu << uint(max(fromBit - 32 * w, 0))) &
                            (0xffffffffu >> uint(31 - min(toBit - 32 * w, 31)));
                while (bits != 0u) {
                    int i = 32 * w + findLSB(bits) - base.x;
                    bits &= bits - 1u;
                    ivec3 anchor = phaseStart + ivec3(i, j, k) * PHASE_STEP;
                    uint fired = firedRule.rule[firedIndex(anchor)];
                    ivec3 fromAnchor = local - anchor;
                    // <<STAMPS>>
                }
            }
        }
    }
}
