#version 450
// <<HEADER>>

// Runs before each phase of its sweep, one invocation per tile (tiles.glsl): a tile is active
// when, for some live rule, every tested cell's value set meets the density range of the
// tiles that cell can read from the tile's anchors of this phase. Ranges are supersets of
// the densities, so a skipped tile holds no anchor where any rule matches. Active tiles are
// appended to ActiveTiles, counted in the record's fourth word, and the record's workgroups
// grow to cover their anchors packed one after another (tiles.glsl, activeAnchorIndex): llvmpipe
// runs every lane of a workgroup through the whole sweep, so a tile's anchors must not leave
// lanes empty (a 4 x 4 x 1 window's phase has 32 anchors per tile, its workgroup 64 lanes).

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

// The tile index of a tile at or after the first of the chunk table, -1 past its end.
int tileIndexOrNone(ivec3 tile) {
    ivec3 tableHigh = (push.chunkBase.xyz + push.chunkCount.xyz) * tilesPerAxis() - 1;
    return any(greaterThan(tile, tableHigh)) ? -1 : tileIndex(tile);
}

// A tile and its next tiles along x, y and z, neighbour k the step (k & 1, k >> 1 & 1, k >> 2):
// their tile indices (tileIndexOrNone) and density ranges (empty outside the chunk table, as
// cellRange leaves such tiles out), each read once per invocation instead of once per tested
// cell. Every cell of a window whose offsets are below 8, the smallest tile size
// (skipTileShift), reads from the anchors of a tile only that tile and the next ones
// (nearCellRange, occupancyRow).
struct TileNeighbourhood {
    ivec3 tile;
    int index[8];
    uvec2 range[8];
};

TileNeighbourhood tileNeighbourhood(ivec3 tile) {
    TileNeighbourhood n;
    n.tile = tile;
    for (int k = 0; k < 8; ++k) {
        n.index[k] = tileIndexOrNone(tile + ivec3(k & 1, (k >> 1) & 1, k >> 2));
        n.range[k] = uvec2(0xffffffffu, 0u);
        if (n.index[k] >= 0) n.range[k] = uvec2(tileRanges.key[2 * n.index[k]], tileRanges.key[2 * n.index[k] + 1]);
    }
    return n;
}

// `range` widened by `other` when `use`.
uvec2 uniteIf(uvec2 range, bool use, uvec2 other) {
    return use ? uvec2(min(range.x, other.x), max(range.y, other.y)) : range;
}

// cellRange for an offset below 8 on every axis, from the neighbourhood of the anchors' tile:
// the same tiles, so the same range.
uvec2 nearCellRange(TileNeighbourhood n, TileAnchors anchors, ivec3 offset) {
    ivec3 from = push.gridOrigin.xyz + push.anchorStart.xyz + anchors.first * push.anchorStep.xyz + offset;
    ivec3 to = push.gridOrigin.xyz + push.anchorStart.xyz + anchors.last * push.anchorStep.xyz + offset;
    bvec3 here = equal(from >> tileShift(), n.tile);       // the reads start in this tile, else in the next
    bvec3 next = greaterThan(to >> tileShift(), n.tile);  // the reads reach the next tile
    uvec2 range = uvec2(0xffffffffu, 0u);
    for (int k = 0; k < 8; ++k) {
        bvec3 step = bvec3((k & 1) != 0, (k & 2) != 0, (k & 4) != 0);
        range = uniteIf(range, all(mix(here, next, step)), n.range[k]);
    }
    return range;
}

// The occupancy bits of row (y, z) of the neighbourhood (tile-local, 0 <= y, z < 2 * tileSize()),
// bit x for x = 0 .. 2 * tileSize() - 1: the tile's row, then its next tile's along x. Outside
// the chunk table no anchor's window reads, so those bits are clear.
uint occupancyRow(TileNeighbourhood n, int y, int z) {
    int size = tileSize();
    bool upY = y >= size;
    bool upZ = z >= size;
    int here = upZ ? (upY ? n.index[6] : n.index[4]) : (upY ? n.index[2] : n.index[0]);
    int next = upZ ? (upY ? n.index[7] : n.index[5]) : (upY ? n.index[3] : n.index[1]);
    ivec3 inside = ivec3(0, y & (size - 1), z & (size - 1));
    uint rowMask = (1u << size) - 1u;
    uint row = 0u;
    if (here >= 0) {
        ivec2 bit = occupancyBit(here, inside);
        row = (tileOccupancy.bits[bit.x] >> bit.y) & rowMask;
    }
    if (next >= 0) {
        ivec2 bit = occupancyBit(next, inside);
        row |= ((tileOccupancy.bits[bit.x] >> bit.y) & rowMask) << size;
    }
    return row;
}

// Whether a density range (keys) meets the key interval [lo, hi].
bool meets(uvec2 range, uint lo, uint hi) {
    return range.x <= hi && lo <= range.y;
}

void main() {
    uint id = gl_GlobalInvocationID.x;
    uint record = uint(push.anchorStart.w);
    uint groupsX = activeDispatchGroupsX(SWEEP_WORKGROUP_INVOCATIONS);
    if (id == 0u) {
        activeDispatch.args[4u * record] = groupsX;
        activeDispatch.args[4u * record + 2u] = 1u;
        // the next phase's record starts with no tile
        activeDispatch.args[4u * (1u - record) + 1u] = 0u;
        activeDispatch.args[4u * (1u - record) + 3u] = 0u;
    }
    if (id >= uint(push.chunkCount.x * push.chunkCount.y * push.chunkCount.z * tilesPerChunk())) return;
    TileAnchors anchors = tileAnchors(tileOfId(id));
    if (any(greaterThan(anchors.first, anchors.last))) return;

    // <<MAY_MATCH>>

    if (!mayMatch) return;
    atomicAdd(skipStats.activeTilePhases, 1u);
    uint slot = atomicAdd(activeDispatch.args[4u * record + 3u], 1u);
    activeTiles.id[slot] = id;
    // Rows of groupsX workgroups enough for the anchors of the tiles up to this one.
    uint lanes = (slot + 1u) * uint(anchorsPerTileCount());
    uint rowLanes = groupsX * uint(SWEEP_WORKGROUP_INVOCATIONS);
    atomicMax(activeDispatch.args[4u * record + 1u], (lanes + rowLanes - 1u) / rowLanes);
}
