#version 450
// voxc runtime kernel "tile_ranges": recomputes the exact density range of every tile whose
// flag in TileDirty is set (after a start stage, or where a sweep wrote), so the next sweep
// classifies tiles on tight ranges. One invocation per tile id (tiles.glsl); a workgroup per
// tile would cost more in workgroup overhead (llvmpipe) than the tile's reads, and workgroups of
// 8 (one llvmpipe batch) spread the tiles over its threads more evenly than 64 did. Only voxels
// inside the grid count, since windows never read the padding (their occupancy bits stay clear).
// The same reads set the tile's occupancy bits (tiles.glsl).

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

// A column walk along y (anchor step 1) goes in runs that stay inside one chunk: the run starting
// at grid-local voxel `local` (walk index y) ends before index columnRunEnd, at `last` at the latest;
// its first address comes from the chunk table and each next one is chunkSize further. Every lane
// of a dispatch walks the same y, so the runs end together: llvmpipe leaves a loop once all lanes
// have, but runs both sides of a branch, so a lookup under `if` would cost every voxel.
int columnRunEnd(ivec3 local, int y, int last) {
    int chunkSize = push.gridOrigin.w;
    int worldY = push.gridOrigin.y + local.y;
    return min(last, y + chunkSize - (worldY & (chunkSize - 1)));
}
// ---- end common.glsl ----

layout(local_size_x = 8, local_size_y = 1, local_size_z = 1) in;

// ---- begin tiles.glsl ----
// Per-tile bookkeeping that lets the runtime dispatch a sweep only over the tiles where some
// rule may match (bindings 3-7 and 13, kBindingTileRanges.. in KernelPackage.h). Include after the
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
    uint activeTilePhases; // (tile, phase) pairs dispatched in this run (the runtime counts the candidates)
} skipStats;

layout(std430, set = 0, binding = 13) buffer TileOccupancy {
    uint bits[]; // per tile: a bit per voxel, set where the occupancy level holds (occupancyBit)
} tileOccupancy;

// The package's occupancy level (ActiveTilesKernel.cpp, occupancyLevel): a density test many rule
// cells need to pass or to fail, such as `d >= 0.5` for rock. Tiles of at most 16 voxels per axis
// keep one bit per voxel of it, exact at all times (tile_ranges sets the bits, sweeps update the
// bits they write), so the active-tiles kernels can look for a rule's pattern of rock and air
// rows at a time instead of trusting a density range. NaN never holds.
const bool OCCUPANCY_LEVEL = true;
bool occupied(float density) { return density >= 0.5; }

uint densityKey(float v) {
    uint bits = floatBitsToUint(v);
    return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
}

int tileShift() { return push.anchorStep.w; }
int tileSize() { return push.gridOrigin.w >> (findMSB(push.gridOrigin.w) - push.anchorStep.w); }
int tilesPerAxis() { return push.gridOrigin.w >> push.anchorStep.w; } // per chunk, a power of two
int tilesPerAxisShift() { return findMSB(push.gridOrigin.w) - push.anchorStep.w; } // its log2
int tilesPerChunk() { return tilesPerAxis() * tilesPerAxis() * tilesPerAxis(); }

// Whether tiles keep occupancy bits: a tile row of voxels and the next tile's then fit one uint.
bool occupancyTracked() { return OCCUPANCY_LEVEL && tileShift() <= 4; }
int occupancyWordsPerTile() { return 1 << (3 * tileShift() - 5); }
// Where voxel `inside` (tile-local) of tile `index` keeps its bit: word, then the bit's position.
// A row along x is tileSize() bits of one word (tiles of 8 or 16 voxels per axis).
ivec2 occupancyBit(int index, ivec3 inside) {
    int bit = (inside.x + tileSize() * (inside.y + tileSize() * inside.z));
    return ivec2(index * occupancyWordsPerTile() + (bit >> 5), bit & 31);
}

// a / b for a >= 0, b >= 1 and a quotient below 2^21, as integer division computes it. llvmpipe
// divides integers lane by lane (and guards each against zero); this is a few float and integer
// operations on every lane at once. The float quotient is off by less than 1 there (even with
// the 2.5 ulp division Vulkan allows), so one correction either way makes it exact. Every
// quotient below counts tiles, chunks or anchors of a grid, which stay below 2^21.
int smallQuotient(int a, int b) {
    int q = int(float(a) * (1.0 / float(b)));
    int r = a - q * b;
    return q + (r >= b ? 1 : 0) - (r < 0 ? 1 : 0);
}
ivec3 smallQuotient(ivec3 a, ivec3 b) {
    return ivec3(smallQuotient(a.x, b.x), smallQuotient(a.y, b.y), smallQuotient(a.z, b.z));
}

// Tile index of the tile at world tile coordinate `tile`.
int tileIndex(ivec3 tile) {
    int perAxis = tilesPerAxis();
    ivec3 entry = (tile >> tilesPerAxisShift()) - push.chunkBase.xyz;
    int slot = chunkTable.chunkSlot[entry.x + push.chunkCount.x * (entry.y + push.chunkCount.y * entry.z)];
    ivec3 inside = tile & (perAxis - 1);
    return slot * tilesPerChunk() + inside.x + perAxis * (inside.y + perAxis * inside.z);
}

// World tile coordinate of a tile id.
ivec3 tileOfId(uint id) {
    int shift = tilesPerAxisShift();
    int perAxis = tilesPerAxis();
    int entry = int(id) >> (3 * shift);
    int inside = int(id) & (tilesPerChunk() - 1);
    ivec3 count = push.chunkCount.xyz;
    int row = smallQuotient(entry, count.x); // entry / count.x
    int plane = smallQuotient(row, count.y);
    ivec3 chunk = push.chunkBase.xyz + ivec3(entry - row * count.x, row - plane * count.y, plane);
    return chunk * perAxis + (ivec3(inside, inside >> shift, inside >> (2 * shift)) & (perAxis - 1));
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
    a.first = smallQuotient(max(low, ivec3(0)) + step - 1, step);
    // floor(high / step), and -1 when the tile ends before the first anchor
    a.last = min(mix(smallQuotient(max(high, ivec3(0)), step), ivec3(-1), lessThan(high, ivec3(0))),
                 push.anchorCount.xyz - 1);
    return a;
}

// Most anchors of the current phase one tile can hold per axis: how the sweep's indirect
// dispatch spreads a tile's anchors over workgroups.
ivec3 anchorsPerTile() {
    ivec3 step = push.anchorStep.xyz;
    return min(smallQuotient(ivec3(tileSize()) + step - 1, step), push.anchorCount.xyz);
}
int anchorsPerTileCount() {
    ivec3 n = anchorsPerTile();
    return n.x * n.y * n.z;
}

// Workgroups per row of an indirect sweep dispatch: enough for one tile's anchors, so the rows
// (workgroup y) never outnumber the active tiles (voxc::skipTileShift checks them against the limit).
uint activeDispatchGroupsX(int workgroupInvocations) {
    return uint(smallQuotient(anchorsPerTileCount() + workgroupInvocations - 1, workgroupInvocations));
}

// An indirect sweep's lanes take the active tiles' anchors one after another: lane `lane` of
// the dispatch is anchor `anchor` of active tile `slot`; false past the last active tile.
bool activeAnchorIndex(uint record, uint lane, out uint slot, out int anchor) {
    int perTile = anchorsPerTileCount();
    slot = uint(smallQuotient(int(lane), perTile));
    anchor = int(lane) - int(slot) * perTile;
    return slot < activeDispatch.args[4u * record + 3u];
}
// ---- end tiles.glsl ----

void main() {
    uint id = gl_GlobalInvocationID.x;
    if (id >= uint(push.chunkCount.x * push.chunkCount.y * push.chunkCount.z * tilesPerChunk())) return;
    ivec3 tile = tileOfId(id);
    int index = tileIndex(tile);
    if (tileDirty.flag[index] == 0u) return;
    ivec3 tileLow = tile * tileSize() - push.gridOrigin.xyz; // grid-local
    ivec3 low = max(tileLow, ivec3(0)) - tileLow;             // tile-local, the in-grid part
    ivec3 high = min(tileLow + tileSize(), push.gridSize.xyz) - tileLow;
    bool occupancy = occupancyTracked();
    uint lo = 0xffffffffu;
    uint hi = 0u;
    uint word = 0u; // occupancy rows gathered for the word they fill
    // A tile lies inside one chunk: its voxels' addresses step by 1, chunkSize and chunkSize^2.
    int chunkSize = push.gridOrigin.w;
    int lowAddress = voxelAddress(tileLow + low);
    for (int z = 0; z < tileSize(); ++z) {
        for (int y = 0; y < tileSize(); ++y) {
            uint row = 0u;
            if (z >= low.z && z < high.z && y >= low.y && y < high.y) {
                int address = lowAddress + chunkSize * ((y - low.y) + chunkSize * (z - low.z));
                for (int x = low.x; x < high.x; ++x, ++address) {
                    float density = voxels.density[address];
                    uint key = densityKey(density);
                    lo = min(lo, key);
                    hi = max(hi, key);
                    row |= uint(occupied(density)) << x;
                }
            }
            if (!occupancy) continue;
            ivec2 bit = occupancyBit(index, ivec3(0, y, z));
            word |= row << bit.y;
            if (bit.y + tileSize() == 32) {
                tileOccupancy.bits[bit.x] = word;
                word = 0u;
            }
        }
    }
    tileRanges.key[2 * index] = lo;
    tileRanges.key[2 * index + 1] = hi;
    tileDirty.flag[index] = 0u;
}
