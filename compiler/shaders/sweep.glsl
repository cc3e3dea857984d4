#version 450
// <<HEADER>>

// One sweep of a grammar: all rules of one window size. One invocation per anchor of the
// current phase; the windows of one phase never overlap, so every invocation owns its cells. The steps mirror the CPU interpreter: read the window, find the matching
// rules, choose one (voxc::chooseRule), then apply its transform.

#include "common.glsl"
#include "random.glsl"

// <<DISPATCH_SHAPE>>

// <<RULE_TABLE>>

// The two draws of voxc::chooseRule at one anchor: which matched rule, and whether it fires.
uint ruleChoiceDraw(ivec3 anchorWorld) {
    return anchorHash(uint(push.gridSize.w), uint(push.chunkBase.w), uint(push.chunkCount.w), anchorWorld,
                      STREAM_RULE_CHOICE);
}
uint probabilityDraw(ivec3 anchorWorld) {
    return anchorHash(uint(push.gridSize.w), uint(push.chunkBase.w), uint(push.chunkCount.w), anchorWorld,
                      STREAM_PROBABILITY) >> 8;
}

// Where the cells of a window lie in the voxel buffer. A window inside one chunk (the common
// case) is addressed from the anchor's address; one straddling a chunk border looks every cell up.
struct WindowAddressing {
    ivec3 anchor;
    int anchorAddress;
    bool oneChunk;
};

WindowAddressing windowAddressing(ivec3 anchor, ivec3 size) {
    int chunkSize = push.gridOrigin.w;
    ivec3 inside = (push.gridOrigin.xyz + anchor) & (chunkSize - 1);
    return WindowAddressing(anchor, voxelAddress(anchor), all(lessThanEqual(inside + size, ivec3(chunkSize))));
}

int windowCellAddress(WindowAddressing window, ivec3 offset) {
    int chunkSize = push.gridOrigin.w;
    if (window.oneChunk) return window.anchorAddress + offset.x + chunkSize * (offset.y + chunkSize * offset.z);
    return voxelAddress(window.anchor + offset);
}

// One invocation per anchor (ANCHORS_PER_INVOCATION is 1): a loop over several anchors with
// run-time bounds costs more than it saves on llvmpipe.
void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(id, push.anchorCount.xyz))) return;
    ivec3 anchor = push.anchorStart.xyz + id * push.anchorStep.xyz;
    ivec3 anchorWorld = push.gridOrigin.xyz + anchor;

    // <<MATCH_WINDOW>>

    // <<CHOOSE_RULE>>

    // <<APPLY_RULE>>
}
