#version 450
// <<HEADER>>

// One sweep of a grammar: all rules of one window size. One invocation per anchor of the
// current phase; the windows of one phase never overlap, so every invocation owns its cells.
// The steps mirror the CPU interpreter: read the window, find the matching rules, choose one
// (voxc::chooseRule), then apply its transform.
//
// Two ways to dispatch it (push.anchorCount.w): 0, directly over every anchor of the phase;
// 1, indirectly over the tiles the sweep's active-tiles kernel found (tiles.glsl), their
// anchors packed one after another over the dispatch's lanes (activeAnchorIndex).

#include "common.glsl"
#include "random.glsl"
#include "nonfinite.glsl"

// <<DISPATCH_SHAPE>>

#include "tiles.glsl"

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

// Stores a written density and keeps its tile's range a superset of the tile's densities
// (the range only widens; the next tile_ranges pass recomputes it exactly) and the voxel's
// occupancy bit exact (other lanes write other bits of the word, hence the atomics).
void writeDensity(int address, float value) {
    voxels.density[address] = value;
    if (push.anchorCount.w == 0) return; // direct dispatch: no tile bookkeeping
    int chunkSize = push.gridOrigin.w;
    int chunkShift = findMSB(chunkSize);
    int inside = address & (chunkSize * chunkSize * chunkSize - 1);
    int perAxis = tilesPerAxis();
    ivec3 voxel = ivec3(inside, inside >> chunkShift, inside >> (2 * chunkShift)) & (chunkSize - 1);
    ivec3 tile = voxel >> tileShift();
    int index = (address >> (3 * chunkShift)) * tilesPerChunk() + tile.x + perAxis * (tile.y + perAxis * tile.z);
    uint key = densityKey(value);
    atomicMin(tileRanges.key[2 * index], key);
    atomicMax(tileRanges.key[2 * index + 1], key);
    tileDirty.flag[index] = 1u;
    if (!occupancyTracked()) return;
    ivec2 bit = occupancyBit(index, voxel & (tileSize() - 1));
    if (occupied(value))
        atomicOr(tileOccupancy.bits[bit.x], 1u << bit.y);
    else
        atomicAnd(tileOccupancy.bits[bit.x], ~(1u << bit.y));
}

// The anchor of this invocation in an indirect dispatch: false when it has none.
bool activeTileAnchor(out ivec3 anchor) {
    uint workgroup = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    uint slot;
    int t;
    anchor = ivec3(0);
    if (!activeAnchorIndex(uint(push.anchorStart.w), workgroup * (gl_WorkGroupSize.x * gl_WorkGroupSize.y * gl_WorkGroupSize.z) +
                           gl_LocalInvocationIndex, slot, t))
        return false;
    TileAnchors anchors = tileAnchors(tileOfId(activeTiles.id[slot]));
    ivec3 n = anchorsPerTile();
    int row = smallQuotient(t, n.x); // t / n.x
    int plane = smallQuotient(row, n.y);
    ivec3 i = anchors.first + ivec3(t - row * n.x, row - plane * n.y, plane);
    anchor = push.anchorStart.xyz + i * push.anchorStep.xyz;
    return all(lessThanEqual(i, anchors.last));
}

// One invocation per anchor (ANCHORS_PER_INVOCATION is 1): a loop over several anchors with
// run-time bounds costs more than it saves on llvmpipe.
void main() {
    ivec3 anchor;
    if (push.anchorCount.w != 0) {
        if (!activeTileAnchor(anchor)) return;
    } else {
        ivec3 id = ivec3(gl_GlobalInvocationID);
        if (any(greaterThanEqual(id, push.anchorCount.xyz))) return;
        anchor = push.anchorStart.xyz + id * push.anchorStep.xyz;
    }
    ivec3 anchorWorld = push.gridOrigin.xyz + anchor;

    // <<MATCH_WINDOW>>

    // <<CHOOSE_RULE>>

    // <<APPLY_RULE>>
}
