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

// The ranges of a tile and of its next tiles along x, y and z (rxyz: x, y, z steps of 0 or 1),
// each read once per invocation instead of once per tested cell; a tile outside the chunk table
// has the empty range, as cellRange leaves it out. Every cell of a window whose offsets are
// below 8, the smallest tile size (skipTileShift), reads from the anchors of a tile only that
// tile and the next ones (nearCellRange).
struct TileNeighbourhood {
    ivec3 tile;
    uvec2 r000, r100, r010, r110, r001, r101, r011, r111;
};

// The tile index of a tile at or after the first of the chunk table, -1 past its end.
int tileIndexOrNone(ivec3 tile) {
    ivec3 tableHigh = (push.chunkBase.xyz + push.chunkCount.xyz) * tilesPerAxis() - 1;
    return any(greaterThan(tile, tableHigh)) ? -1 : tileIndex(tile);
}

uvec2 tileRangeOrEmpty(ivec3 tile) {
    int index = tileIndexOrNone(tile);
    if (index < 0) return uvec2(0xffffffffu, 0u);
    return uvec2(tileRanges.key[2 * index], tileRanges.key[2 * index + 1]);
}

TileNeighbourhood tileNeighbourhood(ivec3 tile) {
    TileNeighbourhood n;
    n.tile = tile;
    n.r000 = tileRangeOrEmpty(tile);
    n.r100 = tileRangeOrEmpty(tile + ivec3(1, 0, 0));
    n.r010 = tileRangeOrEmpty(tile + ivec3(0, 1, 0));
    n.r110 = tileRangeOrEmpty(tile + ivec3(1, 1, 0));
    n.r001 = tileRangeOrEmpty(tile + ivec3(0, 0, 1));
    n.r101 = tileRangeOrEmpty(tile + ivec3(1, 0, 1));
    n.r011 = tileRangeOrEmpty(tile + ivec3(0, 1, 1));
    n.r111 = tileRangeOrEmpty(tile + ivec3(1, 1, 1));
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
    range = uniteIf(range, here.x && here.y && here.z, n.r000);
    range = uniteIf(range, next.x && here.y && here.z, n.r100);
    range = uniteIf(range, here.x && next.y && here.z, n.r010);
    range = uniteIf(range, next.x && next.y && here.z, n.r110);
    range = uniteIf(range, here.x && here.y && next.z, n.r001);
    range = uniteIf(range, next.x && here.y && next.z, n.r101);
    range = uniteIf(range, here.x && next.y && next.z, n.r011);
    range = uniteIf(range, next.x && next.y && next.z, n.r111);
    return range;
}

// The tile indices (tileIndexOrNone) of a tile and its next
// tiles along x, y and z: where the occupancy rows of a window whose offsets are below 8 lie.
struct OccupancyNeighbourhood {
    int i000, i100, i010, i110, i001, i101, i011, i111;
};

OccupancyNeighbourhood occupancyNeighbourhood(ivec3 tile) {
    OccupancyNeighbourhood n;
    n.i000 = tileIndexOrNone(tile);
    n.i100 = tileIndexOrNone(tile + ivec3(1, 0, 0));
    n.i010 = tileIndexOrNone(tile + ivec3(0, 1, 0));
    n.i110 = tileIndexOrNone(tile + ivec3(1, 1, 0));
    n.i001 = tileIndexOrNone(tile + ivec3(0, 0, 1));
    n.i101 = tileIndexOrNone(tile + ivec3(1, 0, 1));
    n.i011 = tileIndexOrNone(tile + ivec3(0, 1, 1));
    n.i111 = tileIndexOrNone(tile + ivec3(1, 1, 1));
    return n;
}

// The occupancy bits of row (y, z) of the neighbourhood (tile-local, 0 <= y, z < 2 * tileSize()),
// bit x for x = 0 .. 2 * tileSize() - 1: the tile's row, then its next tile's along x. Outside
// the chunk table no anchor's window reads, so those bits are clear.
uint occupancyRow(OccupancyNeighbourhood n, int y, int z) {
    int size = tileSize();
    bool upY = y >= size;
    bool upZ = z >= size;
    int here = upZ ? (upY ? n.i011 : n.i001) : (upY ? n.i010 : n.i000);
    int next = upZ ? (upY ? n.i111 : n.i101) : (upY ? n.i110 : n.i100);
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
