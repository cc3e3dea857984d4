// Per-tile bookkeeping that lets the runtime dispatch a sweep only over the tiles where some
// rule may match (bindings 3-7, kBindingTileRanges.. in KernelPackage.h). Include after the
// kernel's local size layout.
//
// A tile is a cube of 2^push.anchorStep.w voxels per axis, aligned to world coordinates like
// the chunks and never larger than one, so each chunk holds tilesPerChunk() tiles. Tile
// buffers are indexed by tileIndex (chunk slot, then the tile inside it); the runtime
// enumerates tiles by tile id (chunk-table entry, then the tile inside it).
//
// A density range is kept as two order-preserving keys (densityKey): a < b as floats implies
// key(a) < key(b) as uints, so ranges widen with atomicMin/atomicMax and compare exactly in
// integers. -0 sorts just below +0; NaNs sort beyond the infinities.

layout(std430, set = 0, binding = 3) buffer TileRanges {
    uint key[]; // per tile: lowest key, highest key (a superset of the tile's in-grid densities)
} tileRanges;

layout(std430, set = 0, binding = 4) buffer TileDirty {
    uint flag[]; // per tile: written since its range was last computed exactly
} tileDirty;

layout(std430, set = 0, binding = 5) buffer ActiveTiles {
    uint id[]; // tile ids the current phase runs on
} activeTiles;

layout(std430, set = 0, binding = 6) buffer ActiveDispatch {
    uint args[]; // two VkDispatchIndirectCommand records (x, y, z) and each one's active tile count
} activeDispatch;

layout(std430, set = 0, binding = 7) buffer SkipStats {
    uint activeTilePhases;    // (tile, phase) pairs dispatched in this run
    uint candidateTilePhases; // (tile, phase) pairs holding anchors of a classified phase
} skipStats;

uint densityKey(float v) {
    uint bits = floatBitsToUint(v);
    return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
}

int tileShift() { return push.anchorStep.w; }
int tileSize() { return push.gridOrigin.w >> (findMSB(push.gridOrigin.w) - push.anchorStep.w); }
int tilesPerAxis() { return push.gridOrigin.w >> push.anchorStep.w; } // per chunk
int tilesPerChunk() { return tilesPerAxis() * tilesPerAxis() * tilesPerAxis(); }

// Tile index of the tile at world tile coordinate `tile`.
int tileIndex(ivec3 tile) {
    int perAxis = tilesPerAxis();
    ivec3 entry = (tile >> findMSB(perAxis)) - push.chunkBase.xyz;
    int slot = chunkTable.chunkSlot[entry.x + push.chunkCount.x * (entry.y + push.chunkCount.y * entry.z)];
    ivec3 inside = tile & (perAxis - 1);
    return slot * tilesPerChunk() + inside.x + perAxis * (inside.y + perAxis * inside.z);
}

// World tile coordinate of a tile id.
ivec3 tileOfId(uint id) {
    int perAxis = tilesPerAxis();
    int entry = int(id) / tilesPerChunk();
    int inside = int(id) % tilesPerChunk();
    ivec3 count = push.chunkCount.xyz;
    ivec3 chunk = push.chunkBase.xyz + ivec3(entry % count.x, entry / count.x % count.y, entry / (count.x * count.y));
    return chunk * perAxis + ivec3(inside % perAxis, inside / perAxis % perAxis, inside / (perAxis * perAxis));
}

// The anchors of the current phase (push.anchorStart + i * step, i < push.anchorCount) whose
// anchor voxel lies in `tile`: indices first..last per axis, none when first > last on an
// axis. Every anchor belongs to exactly one tile.
struct TileAnchors {
    ivec3 first;
    ivec3 last;
};

TileAnchors tileAnchors(ivec3 tile) {
    ivec3 step = push.anchorStep.xyz;
    ivec3 low = tile * tileSize() - push.gridOrigin.xyz - push.anchorStart.xyz;
    ivec3 high = low + (tileSize() - 1);
    TileAnchors a;
    a.first = (max(low, ivec3(0)) + step - 1) / step;
    // floor(high / step), and -1 when the tile ends before the first anchor
    a.last = min(mix(high / step, ivec3(-1), lessThan(high, ivec3(0))), push.anchorCount.xyz - 1);
    return a;
}

// Most anchors of the current phase one tile can hold per axis: how the sweep's indirect
// dispatch spreads a tile's anchors over workgroups.
ivec3 anchorsPerTile() {
    ivec3 step = push.anchorStep.xyz;
    return min((ivec3(tileSize()) + step - 1) / step, push.anchorCount.xyz);
}
int anchorsPerTileCount() {
    ivec3 n = anchorsPerTile();
    return n.x * n.y * n.z;
}

// Workgroups per row of an indirect sweep dispatch: enough for one tile's anchors, so the rows
// (workgroup y) never outnumber the active tiles (voxc::skipTileShift checks them against the limit).
uint activeDispatchGroupsX(int workgroupInvocations) {
    return uint(anchorsPerTileCount() + workgroupInvocations - 1) / uint(workgroupInvocations);
}

// An indirect sweep's lanes take the active tiles' anchors one after another: lane `lane` of
// the dispatch is anchor `anchor` of active tile `slot`; false past the last active tile.
bool activeAnchorIndex(uint record, uint lane, out uint slot, out int anchor) {
    uint perTile = uint(anchorsPerTileCount());
    slot = lane / perTile;
    anchor = int(lane % perTile);
    return slot < activeDispatch.args[4u * record + 3u];
}
