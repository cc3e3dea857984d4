#version 450
// voxc generated kernel "overhang_sweep1_active_tiles": the active tiles of each phase of sweep 1 (window [1, 2, 1]) of
// grammar overhang (sample.vox:8:1).

// Runs before each phase of its sweep, one invocation per tile (tiles.glsl): a tile is active
// when, for some live rule, every tested cell's value set meets the density range of the
// tiles that cell can read from the tile's anchors of this phase. Ranges are supersets of
// the densities, so a skipped tile holds no anchor where any rule matches. Active tiles are
// appended to ActiveTiles, counted in the record's fourth word, and the record's workgroups
// grow to cover their anchors packed one after another (tiles.glsl, activeAnchorIndex): llvmpipe
// runs every lane of a workgroup through the whole sweep, so a tile's anchors must not leave
// lanes empty (a 4 x 4 x 1 window's phase has 32 anchors per tile, its workgroup 64 lanes).

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

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
// Each invocation handles this many consecutive anchors of its dispatch per axis
// (voxc::Kernel::anchorsPerInvocation; the runtime sizes the dispatch by it).
const ivec3 ANCHORS_PER_INVOCATION = ivec3(1, 1, 1);

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

    // The density range each tested cell can read (keys), over this tile's anchors.
    TileNeighbourhood neighbourhood = tileNeighbourhood(tileOfId(id));
    uvec2 range0 = nearCellRange(neighbourhood, anchors, ivec3(0, 0, 0));
    uvec2 range1 = nearCellRange(neighbourhood, anchors, ivec3(0, 1, 0));

    // A rule may match when each of its tested cells' value sets meets that cell's range.
    bool mayMatch = false;
    // 0: settle
    bool ranges0 =
        meets(range0, 0x80000001u, 0xffffffffu) && // (0, 0, 0) PRES
        meets(range1, 0x7fffffffu, 0x80000000u); // (0, 1, 0) ABS
    mayMatch = mayMatch || (ranges0 && !occupancyTracked());

    // Rules whose ranges pass and whose cells the occupancy level decides: look for their
    // patterns of voxels holding (row bits) and failing it (~) at this phase's anchors, a row
    // of anchors at a time (bit x: the anchor at tile-local x).
    if (!mayMatch && (ranges0)) {
        ivec3 localStart = push.gridOrigin.xyz + push.anchorStart.xyz - neighbourhood.tile * tileSize();
        uint anchorsX = 0u;
        for (int i = anchors.first.x; i <= anchors.last.x; ++i) anchorsX |= 1u << (localStart.x + i * push.anchorStep.x);
        for (int iz = anchors.first.z; iz <= anchors.last.z && !mayMatch; ++iz) {
            int z = localStart.z + iz * push.anchorStep.z;
            for (int iy = anchors.first.y; iy <= anchors.last.y && !mayMatch; ++iy) {
                int y = localStart.y + iy * push.anchorStep.y;
                uint row_1_0 = occupancyRow(neighbourhood, y + 1, z + 0);
                mayMatch = mayMatch || (ranges0 && (anchorsX & (~row_1_0 >> 0)) != 0u); // settle
            }
        }
    }

    if (!mayMatch) return;
    atomicAdd(skipStats.activeTilePhases, 1u);
    uint slot = atomicAdd(activeDispatch.args[4u * record + 3u], 1u);
    activeTiles.id[slot] = id;
    // Rows of groupsX workgroups enough for the anchors of the tiles up to this one.
    uint lanes = (slot + 1u) * uint(anchorsPerTileCount());
    uint rowLanes = groupsX * uint(SWEEP_WORKGROUP_INVOCATIONS);
    atomicMax(activeDispatch.args[4u * record + 1u], (lanes + rowLanes - 1u) / rowLanes);
}
