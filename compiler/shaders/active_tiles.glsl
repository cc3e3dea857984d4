#version 450
// <<HEADER>>

// Runs before each phase of its sweep, one invocation per tile (tiles.glsl): a tile is active
// when, for some live rule, every tested cell's value set meets the density range of the
// tiles that cell can read from the tile's anchors of this phase. Ranges are supersets of
// the densities, so a skipped tile holds no anchor where any rule matches. Active tiles are
// appended to ActiveTiles and counted into the phase's indirect dispatch record.

#include "common.glsl"

// <<DISPATCH_SHAPE>>

#include "tiles.glsl"

// <<SWEEP_SHAPE>>

// Union of the ranges of the tiles cell `offset` of a window reads from the given anchors.
uvec2 cellRange(TileAnchors anchors, ivec3 offset) {
    ivec3 from = push.gridOrigin.xyz + push.anchorStart.xyz + anchors.first * push.anchorStep.xyz + offset;
    ivec3 to = push.gridOrigin.xyz + push.anchorStart.xyz + anchors.last * push.anchorStep.xyz + offset;
    ivec3 tableLow = push.chunkBase.xyz * tilesPerAxis();
    ivec3 firstTile = max(from >> tileShift(), tableLow);
    ivec3 lastTile = min(to >> tileShift(), tableLow + push.chunkCount.xyz * tilesPerAxis() - 1);
    uvec2 range = uvec2(0xffffffffu, 0u);
    for (int z = firstTile.z; z <= lastTile.z; ++z)
        for (int y = firstTile.y; y <= lastTile.y; ++y)
            for (int x = firstTile.x; x <= lastTile.x; ++x) {
                int index = tileIndex(ivec3(x, y, z));
                range.x = min(range.x, tileRanges.key[2 * index]);
                range.y = max(range.y, tileRanges.key[2 * index + 1]);
            }
    return range;
}

// Whether a density range (keys) meets the key interval [lo, hi].
bool meets(uvec2 range, uint lo, uint hi) {
    return range.x <= hi && lo <= range.y;
}

void main() {
    uint id = gl_GlobalInvocationID.x;
    uint record = uint(push.anchorStart.w);
    if (id == 0u) {
        ivec3 n = anchorsPerTile();
        activeDispatch.args[4u * record] = uint(n.x * n.y * n.z + SWEEP_WORKGROUP_INVOCATIONS - 1) /
                                           uint(SWEEP_WORKGROUP_INVOCATIONS);
        activeDispatch.args[4u * record + 2u] = 1u;
        activeDispatch.args[4u * (1u - record) + 1u] = 0u; // the next phase's record starts with no tile
    }
    if (id >= uint(push.chunkCount.x * push.chunkCount.y * push.chunkCount.z * tilesPerChunk())) return;
    TileAnchors anchors = tileAnchors(tileOfId(id));
    if (any(greaterThan(anchors.first, anchors.last))) return;
    atomicAdd(skipStats.candidateTilePhases, 1u);

    // <<MAY_MATCH>>

    if (!mayMatch) return;
    atomicAdd(skipStats.activeTilePhases, 1u);
    activeTiles.id[atomicAdd(activeDispatch.args[4u * record + 1u], 1u)] = id;
}
