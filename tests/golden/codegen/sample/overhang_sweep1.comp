#version 450
// voxc generated kernel "overhang_sweep1" from sample.vox:8:1 grammar overhang.
// Sweep 1 runs every rule of window [1, 2, 1]: [20, 11, 10] anchors in [1, 2, 1] phases.
// Grammar stride [1, 1, 1], bounds [0, 0, 0]..[20, 12, 10], 4 iteration(s), clamp [0.0, 1.0].
// Rules (declaration order):
//   settle (sample.vox:33:3): priority 0, weight 1000 units, probability 16777216 / 2^24

// One sweep of a grammar: all rules of one window size. One invocation per anchor of the
// current phase; the windows of one phase never overlap, so every invocation owns its cells.
// The steps mirror the CPU interpreter: read the window, find the matching rules, choose one
// (voxc::chooseRule), then apply its transform.

// ---- begin common.glsl ----
// Declarations every voxc kernel shares: the push block (voxc::PushBlock in
// compiler/codegen/include/voxc/codegen/KernelPackage.h, field for field) and the two
// storage buffers of descriptor set 0.

layout(push_constant, std430) uniform PushBlock {
    ivec4 gridOrigin;  // xyz: world coordinate of grid voxel (0,0,0); w: chunk size
    ivec4 gridSize;    // xyz: grid size in voxels; w: seed (bit pattern)
    ivec4 chunkBase;   // xyz: world chunk coordinate of chunk-table entry 0; w: iteration
    ivec4 chunkCount;  // xyz: chunk-table extents; w: sweep index within its grammar
    ivec4 anchorStart; // xyz: grid-local first anchor of this dispatch
    ivec4 anchorStep;  // xyz: distance between the anchors of one dispatch
    ivec4 anchorCount; // xyz: anchors per axis in this dispatch
} push;

// Densities, chunk-major: all voxels of one chunk slot, then the next slot.
layout(std430, set = 0, binding = 0) buffer Voxels {
    float density[];
} voxels;

// Chunk-table entry -> chunk slot; entries run x fastest over push.chunkCount.xyz.
layout(std430, set = 0, binding = 1) readonly buffer ChunkTable {
    int chunkSlot[];
} chunkTable;

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

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

// The live rules of this sweep in declaration order:
//   0: settle (rule 3 of grammar overhang, sample.vox:33:3)
const int RULE_COUNT = 1;
const int RULE_PRIORITY[RULE_COUNT] = int[](0);
const uint RULE_WEIGHT_UNITS[RULE_COUNT] = uint[](1000u);
const uint RULE_PROBABILITY_UNITS[RULE_COUNT] = uint[](16777216u);

// The grammar's clamp, applied to every written value as the CPU does it.
float clampDensity(float v) {
    v = v < 0.0 ? 0.0 : v;
    v = 1.0 < v ? 1.0 : v;
    return v;
}

// voxc::chooseRule: the highest priority among the matched rules wins; equal priorities are
// drawn by weight in declaration order; the chosen rule then fires with its probability.
// Returns the index into the rule table above, or -1 when no rule fires.
int chooseRule(bool matched[RULE_COUNT], ivec3 anchorWorld) {
    bool found = false;
    int best = 0;
    for (int r = 0; r < RULE_COUNT; ++r) {
        if (!matched[r]) continue;
        best = found ? max(best, RULE_PRIORITY[r]) : RULE_PRIORITY[r];
        found = true;
    }
    if (!found) return -1;

    uint total = 0u;
    for (int r = 0; r < RULE_COUNT; ++r)
        if (matched[r] && RULE_PRIORITY[r] == best) total += RULE_WEIGHT_UNITS[r];

    uint seed = uint(push.gridSize.w);
    uint iteration = uint(push.chunkBase.w);
    uint sweep = uint(push.chunkCount.w);
    uint target = anchorHash(seed, iteration, sweep, anchorWorld, STREAM_RULE_CHOICE) % total;
    uint accumulated = 0u;
    int chosen = -1;
    for (int r = 0; r < RULE_COUNT; ++r) {
        if (!matched[r] || RULE_PRIORITY[r] != best) continue;
        accumulated += RULE_WEIGHT_UNITS[r];
        if (target < accumulated) {
            chosen = r;
            break;
        }
    }
    uint draw = anchorHash(seed, iteration, sweep, anchorWorld, STREAM_PROBABILITY) >> 8;
    return draw < RULE_PROBABILITY_UNITS[chosen] ? chosen : -1;
}

void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(id, push.anchorCount.xyz))) return;
    ivec3 anchor = push.anchorStart.xyz + id * push.anchorStep.xyz;
    ivec3 anchorWorld = push.gridOrigin.xyz + anchor;

    // Window [1, 2, 1]: cell i sits at anchor + (i % 1, i / 1 % 2, i / 2).
    int address0 = voxelAddress(anchor + ivec3(0, 0, 0));
    float cell0 = voxels.density[address0];
    int address1 = voxelAddress(anchor + ivec3(0, 1, 0));
    float cell1 = voxels.density[address1];

    // Each distinct predicate of a cell is evaluated once, into one bit of the cell's pass mask.
    uint pass0 = ((cell0 > 0.0) ? 0x1u : 0u); // bit 0: PRES
    uint pass1 = ((cell1 == 0.0) ? 0x1u : 0u); // bit 0: ABS

    // A rule matches when every cell has all the bits the rule needs.
    bool matched[RULE_COUNT];
    // 0: settle (sample.vox:33:3): (0, 0, 0) PRES | (0, 1, 0) ABS
    matched[0] = (pass0 & 0x1u) == 0x1u
              && (pass1 & 0x1u) == 0x1u;

    int chosen = chooseRule(matched, anchorWorld);

    // Apply the chosen rule's transform; NOP cells are left untouched and every written value is clamped.
    if (chosen == 0) { // settle (sample.vox:33:3)
        precise float next0 = (cell0 + -1.0); // (0, 0, 0) ADD -1.0
        voxels.density[address0] = clampDensity(next0);
        precise float next1 = 1.0; // (0, 1, 0) SET 1.0
        voxels.density[address1] = clampDensity(next1);
    }
}
