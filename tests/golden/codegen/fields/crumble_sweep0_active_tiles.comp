#version 450
// voxc generated kernel "crumble_sweep0_active_tiles": the active tiles of each phase of sweep 0 (window [1, 3, 1]) of
// grammar crumble (fields.vox:39:9).

// Runs before each phase of its sweep, one invocation per tile (tiles.glsl): a tile is active
// when, for some live rule, every tested cell's value set meets the density range of the
// tiles that cell can read from the tile's anchors of this phase. Ranges are supersets of
// the densities, so a skipped tile holds no anchor where any rule matches. Active tiles are
// appended to ActiveTiles and counted into the phase's indirect dispatch record.

// ---- begin common.glsl ----
// Declarations every voxc kernel shares: the push block (voxc::PushBlock in
// compiler/codegen/include/voxc/codegen/KernelPackage.h, field for field) and the first three
// storage buffers of descriptor set 0 (kBindingVoxels, kBindingChunkTable, kBindingNoiseTables;
// the chunk-skipping buffers are in chunks.glsl).

layout(push_constant, std430) uniform PushBlock {
    ivec4 gridOrigin;  // xyz: world coordinate of grid voxel (0,0,0); w: chunk size
    ivec4 gridSize;    // xyz: grid size in voxels; w: seed (bit pattern)
    ivec4 chunkBase;   // xyz: world chunk coordinate of chunk-table entry 0; w: iteration
    ivec4 chunkCount;  // xyz: chunk-table extents; w: sweep index within its grammar
    ivec4 anchorStart; // xyz: grid-local first anchor of this dispatch; w: active-dispatch record
    ivec4 anchorStep;  // xyz: distance between the anchors of one dispatch; w: log2 tile size
    ivec4 anchorCount; // xyz: anchors per axis in this dispatch; w: 1 = indirect over active tiles
} push;

// Densities, chunk-major: all voxels of one chunk slot, then the next slot.
layout(std430, set = 0, binding = 0) buffer Voxels {
    float density[];
} voxels;

#ifdef VOXC_MATERIALS
// Material ids (voxc::Material, 0 = none), one uint per voxel at the densities' addresses
// (kBindingMaterials); declared only by kernels of programs that use materials.
layout(std430, set = 0, binding = 8) buffer Materials {
    uint material[];
} materials;
#endif

// Chunk-table entry -> chunk slot; entries run x fastest over push.chunkCount.xyz.
layout(std430, set = 0, binding = 1) readonly buffer ChunkTable {
    int chunkSlot[];
} chunkTable;

// Ken Perlin's 256-entry permutation (voxc::perlinPermutation), read by noise_common.glsl. It is a
// buffer, not a constant array, because some drivers (llvmpipe) materialise a dynamically indexed
// constant array on every call, which cost ~1000x.
layout(std430, set = 0, binding = 2) readonly buffer NoiseTables {
    int perlinPermutation[];
} noiseTables;

// Buffer index of a grid-local voxel, exactly as voxc::ChunkLayout::address computes it.
// Chunks are aligned to world coordinates and their size is a power of two, so the
// arithmetic shift and the mask are floor division and remainder, negatives included.
int voxelAddress(ivec3 local) {
    int chunkSize = push.gridOrigin.w;
    int chunkShift = findMSB(chunkSize);
    ivec3 world = push.gridOrigin.xyz + local;
    ivec3 chunk = world >> chunkShift;
    ivec3 inside = world & (chunkSize - 1);
    ivec3 entry = chunk - push.chunkBase.xyz;
    int slot = chunkTable.chunkSlot[entry.x + push.chunkCount.x * (entry.y + push.chunkCount.y * entry.z)];
    return slot * chunkSize * chunkSize * chunkSize + inside.x + chunkSize * (inside.y + chunkSize * inside.z);
}

// The address of the next voxel of a column walk along y (anchor step 1): looked up through the
// chunk table at the column's first voxel and wherever the column enters a new chunk, otherwise
// the previous voxel's address plus chunkSize (the next voxel along y inside a chunk).
int nextColumnAddress(int previous, bool columnStart, ivec3 local) {
    int chunkSize = push.gridOrigin.w;
    int worldY = push.gridOrigin.y + local.y;
    return (columnStart || (worldY & (chunkSize - 1)) == 0) ? voxelAddress(local) : previous + chunkSize;
}
// ---- end common.glsl ----

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
// Each invocation handles this many consecutive anchors of its dispatch per axis
// (voxc::Kernel::anchorsPerInvocation; the runtime sizes the dispatch by it).
const ivec3 ANCHORS_PER_INVOCATION = ivec3(1, 1, 1);

// ---- begin tiles.glsl ----
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
    uint args[]; // two VkDispatchIndirectCommand records (x, y, z, padding); y counts active tiles
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
// ---- end tiles.glsl ----

// Invocations in one workgroup of the sweep kernel.
const int SWEEP_WORKGROUP_INVOCATIONS = 64;

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

    // The density range each tested cell can read (keys), over this tile's anchors.
    uvec2 range0 = cellRange(anchors, ivec3(0, 0, 0));
    uvec2 range1 = cellRange(anchors, ivec3(0, 1, 0));
    uvec2 range2 = cellRange(anchors, ivec3(0, 2, 0));

    // A rule may match when each of its tested cells' value sets meets that cell's range.
    bool mayMatch = false;
    // 0: thin_overhang
    mayMatch = mayMatch ||
        meets(range0, 0x00000000u, 0xbeffffffu) && // (0, 0, 0) LT 0.5
        meets(range1, 0xbf000000u, 0xffffffffu) && // (0, 1, 0) GEQ 0.5
        meets(range2, 0xbf000000u, 0xffffffffu); // (0, 2, 0) GEQ 0.5

    if (!mayMatch) return;
    atomicAdd(skipStats.activeTilePhases, 1u);
    activeTiles.id[atomicAdd(activeDispatch.args[4u * record + 1u], 1u)] = id;
}
