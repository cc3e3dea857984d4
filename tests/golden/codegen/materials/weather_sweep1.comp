#version 450
#define VOXC_MATERIALS
// voxc generated kernel "weather_sweep1" from materials.vox:60:1 grammar weather.
// Sweep 1 runs every rule of window [1, 2, 1]: [40, 35, 28] anchors in [1, 2, 1] phases.
// Grammar stride [1, 1, 1], bounds [0, 0, 0]..[40, 36, 28], 12 iteration(s), clamp [0.0, 1.0].
// Rules (declaration order):
//   sand_on_top (materials.vox:67:3): priority 0, weight 1000 units, probability 16777216 / 2^24
//   erode_sand (materials.vox:72:3): priority 0, weight 1000 units, probability 8388608 / 2^24

// One sweep of a grammar: all rules of one window size. One invocation per anchor of the
// current phase; the windows of one phase never overlap, so every invocation owns its cells.
// The steps mirror the CPU interpreter: read the window, find the matching rules, choose one
// (voxc::chooseRule), then apply its transform.
//
// Two ways to dispatch it (push.anchorCount.w): 0, directly over every anchor of the phase;
// 1, indirectly over the tiles the sweep's active-tiles kernel found (tiles.glsl), their
// anchors packed one after another over the dispatch's lanes (activeAnchorIndex).

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
// ---- begin random.glsl ----
// Counter-based randomness: mirrors compiler/program/src/Random.cpp bit for bit.

// Chris Wellons' "lowbias32" integer finaliser.
uint mix32(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

const uint STREAM_RULE_CHOICE = 0u;
const uint STREAM_PROBABILITY = 1u;

uint anchorHash(uint seed, uint iteration, uint sweep, ivec3 anchorWorld, uint stream) {
    uint h = mix32(stream);
    h = mix32(uint(anchorWorld.z) ^ h);
    h = mix32(uint(anchorWorld.y) ^ h);
    h = mix32(uint(anchorWorld.x) ^ h);
    h = mix32(sweep ^ h);
    h = mix32(iteration ^ h);
    return mix32(seed ^ h);
}
// ---- end random.glsl ----
// ---- begin nonfinite.glsl ----
// Non-finite densities (docs/language.md, "Non-finite values"), as voxc::NonFiniteCount does it
// on the CPU: a field stage stores 0 where its field is NaN or infinite, a grammar stores 0
// where a written value is not finite, and the stage counts them. The runtime copies this
// buffer out after every stage and resets it to {0, 0, 0xFFFFFFFF} (kBindingNonFinite).
layout(std430, set = 0, binding = 9) buffer NonFinite {
    uint countLow;   // replacements in the current stage, a 64-bit count in two halves
    uint countHigh;
    uint firstIndex; // the lowest grid index x + sx * (y + sy * z) replaced
} nonFinite;

// An exponent of all ones is an infinity or a NaN; tested on the bits, so no float
// optimisation of the driver can change the answer.
bool isFiniteFloat(float v) { return (floatBitsToUint(v) & 0x7F800000u) != 0x7F800000u; }

// `value` when finite; otherwise 0, counted at grid-local voxel `local`.
float finiteDensity(float value, ivec3 local) {
    if (isFiniteFloat(value)) return value;
    if (atomicAdd(nonFinite.countLow, 1u) == 0xFFFFFFFFu) atomicAdd(nonFinite.countHigh, 1u);
    atomicMin(nonFinite.firstIndex, uint(local.x + push.gridSize.x * (local.y + push.gridSize.y * local.z)));
    return 0.0;
}
// ---- end nonfinite.glsl ----

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
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

// The live rules of this sweep in declaration order (matchedN, weightN below):
//   0: sand_on_top (rule 1 of grammar weather, materials.vox:67:3)
//   1: erode_sand (rule 2 of grammar weather, materials.vox:72:3)

// The grammar's clamp, applied to every written value as the CPU does it.
float clampDensity(float v) {
    v = v < 0.0 ? 0.0 : v;
    v = 1.0 < v ? 1.0 : v;
    return v;
}

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

    // Window [1, 2, 1]: cell i sits at anchor + (i % 1, i / 1 % 2, i / 2).
    WindowAddressing window = windowAddressing(anchor, ivec3(1, 2, 1));
    int address0 = 0;
    float cell0 = 0.0;
    uint material0 = 0u;
    int address1 = 0;
    float cell1 = 0.0;
    uint material1 = 0u;

    // The rules' symbols; a rule matches when every cell has all the bits the rule needs.
    // 0: sand_on_top (materials.vox:67:3): (0, 0, 0) GEQ 0.5 & MAT 1 | (0, 1, 0) LT 0.5
    bool matched0 = true;
    // 1: erode_sand (materials.vox:72:3): (0, 0, 0) GEQ 0.5 & MAT 2 | (0, 1, 0) ABS & NMAT 3
    bool matched1 = true;

    // Cell 0 (0, 0, 0): each distinct predicate is one bit of its pass mask.
    address0 = windowCellAddress(window, ivec3(0, 0, 0));
    cell0 = voxels.density[address0];
    material0 = materials.material[address0];
    uint pass0 = ((cell0 >= 0.5) ? 0x1u : 0u) // bit 0: GEQ 0.5
               | ((material0 == 1u) ? 0x2u : 0u) // bit 1: MAT 1
               | ((material0 == 2u) ? 0x4u : 0u); // bit 2: MAT 2
    matched0 = matched0 && (pass0 & 0x3u) == 0x3u;
    matched1 = matched1 && (pass0 & 0x5u) == 0x5u;

    // Cell 1 (0, 1, 0): each distinct predicate is one bit of its pass mask.
    if (matched0 || matched1) {
        address1 = windowCellAddress(window, ivec3(0, 1, 0));
        cell1 = voxels.density[address1];
        material1 = materials.material[address1];
        uint pass1 = ((cell1 < 0.5) ? 0x1u : 0u) // bit 0: LT 0.5
                   | ((cell1 == 0.0) ? 0x2u : 0u) // bit 1: ABS
                   | ((material1 != 3u) ? 0x4u : 0u); // bit 2: NMAT 3
        matched0 = matched0 && (pass1 & 0x1u) == 0x1u;
        matched1 = matched1 && (pass1 & 0x6u) == 0x6u;
    }

    // voxc::chooseRule: the highest priority among the matched rules wins; equal priorities are
    // drawn by weight in declaration order; the chosen rule then fires with its probability.
    uint weight0 = matched0 ? 1000u : 0u;
    uint weight1 = matched1 ? 1000u : 0u;
    uint total = weight0 + weight1;
    int chosen = -1;
    if (total != 0u) {
        uint target = ruleChoiceDraw(anchorWorld) % total;
        // The first rule whose running weight sum exceeds the target, in declaration order.
        uint upTo = weight0;
        chosen = target < upTo ? 0 : -1;
        upTo += weight1;
        if (chosen < 0 && target < upTo) chosen = 1;
        uint probability = chosen == 0 ? 16777216u : 8388608u;
        if (probabilityDraw(anchorWorld) >= probability) chosen = -1;
    }

    // Apply the chosen rule's transform; NOP cells are left untouched, every written value is clamped and a non-finite one is stored as 0.
    if (chosen == 0) { // sand_on_top (materials.vox:67:3)
        materials.material[address0] = 2u; // (0, 0, 0) MAT 2
    } else if (chosen == 1) { // erode_sand (materials.vox:72:3)
        precise float next0 = (cell0 + -0.25); // (0, 0, 0) ADD -0.25
        writeDensity(address0, finiteDensity(clampDensity(next0), anchor + ivec3(0, 0, 0)));
        precise float next1 = 0.5; // (0, 1, 0) SET 0.5 & MAT 1
        writeDensity(address1, finiteDensity(clampDensity(next1), anchor + ivec3(0, 1, 0)));
        materials.material[address1] = 1u; // (0, 1, 0) SET 0.5 & MAT 1
    }
}
