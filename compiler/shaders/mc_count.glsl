#version 450
// GPU marching cubes, pass 1, fused with the first level of the scan: each workgroup takes a
// block of 1024 cells in global key order, each invocation 16 consecutive ones. Per cell: the
// crossed edges it owns (those leaving its minimum corner, one vertex each) and its triangle
// count from the case table; then the block's exclusive prefix sums of (vertices, triangles,
// active cells) and its total for the next scan level (mc_scan.glsl). Consecutive cells of a row
// share a face, so a cell reads the four samples of its +x face and takes the others from the
// cell before it (lavapipe reads a storage buffer one lane at a time, so reads are the cost).
// A cell's place within its block goes to 32-bit words (at most 3 * 1023 vertices, 12 * 1023
// triangles and 1023 active cells come before it): vertices and triangles in cellPlaces, the
// active index above the counts in cellInfo.

layout(local_size_x = 64) in;

// Per case 10 words: the triangle count, then 36 edge indices, four bytes to a word.
layout(std430, set = 0, binding = 2) readonly buffer CaseTable {
    uint word[];
} cases;
layout(std430, set = 0, binding = 3) readonly buffer ChunkFlags {
    uint uniformChunk[];
} flags;
// Bits 0-2: owned crossed edges by axis; bits 3-6: triangle count; above: active index in the block.
layout(std430, set = 0, binding = 4) writeonly buffer CellInfo {
    uint info[];
} cells;
layout(std430, set = 0, binding = 5) writeonly buffer Scan {
    uvec4 value[]; // levels 1 and up at push.levelOffset[level]: vertices, triangles, active cells
} scan;
layout(std430, set = 0, binding = 8) writeonly buffer CellPlace {
    uint place[]; // vertices before the cell in its block | triangles before it << 16
} cellPlaces;

const uint kCellsPerInvocation = 16u;

shared uvec4 partial[64];

bool inUniformChunk(ivec3 cell) {
    const uvec3 chunk = uvec3(((push.gridOrigin.xyz + cell) >> push.gridOrigin.w) - push.cellChunkFirst.xyz);
    const uvec3 counts = uvec3(push.cellChunkCount.xyz);
    return flags.uniformChunk[chunk.x + counts.x * (chunk.y + counts.y * chunk.z)] != 0u;
}

// Solid bits of the four samples of the x = p.x face of a cell at p: bit 0 at p, 1 at +y, 2 at +z, 3 at +y+z.
uint faceBits(ivec3 p) {
    return (solidAt(p) ? 1u : 0u) | (solidAt(p + ivec3(0, 1, 0)) ? 2u : 0u) | (solidAt(p + ivec3(0, 0, 1)) ? 4u : 0u) |
           (solidAt(p + ivec3(0, 1, 1)) ? 8u : 0u);
}

// Face bits at corner offsets x = 0 (corners 0, 2, 4, 6) or x = 1 (corners 1, 3, 5, 7).
uint spread(uint face) { return (face & 1u) | (face & 2u) << 1 | (face & 4u) << 2 | (face & 8u) << 3; }

void main() {
    const uint block = gl_WorkGroupID.y * push.pass.x + gl_WorkGroupID.x;
    const uint count = push.pass.z;
    if (block * 1024u >= count) return; // the whole workgroup
    const uint lane = gl_LocalInvocationID.x;
    const uint first = block * 1024u + lane * kCellsPerInvocation;
    uint infos[kCellsPerInvocation];
    uvec4 sum = uvec4(0u);
    uint highFace = 0u;
    for (uint k = 0u; k < kCellsPerInvocation; ++k) {
        const uint key = first + k;
        uint info = 0u;
        if (key < count) {
            const ivec3 cell = cellOfKey(key);
            // The cell before it in key order is its -x neighbour unless the row starts here.
            const uint lowFace = k == 0u || cell.x == -1 ? faceBits(cell) : highFace;
            highFace = faceBits(cell + ivec3(1, 0, 0));
            if (push.cellChunkCount.w == 0 || !inUniformChunk(cell)) {
                const uint mask = spread(lowFace) | spread(highFace) << 1;
                const bool lowerSolid = (mask & 1u) != 0u;
                for (uint axis = 0u; axis < 3u; ++axis)
                    if (lowerSolid != (((mask >> (1u << axis)) & 1u) != 0u)) info |= 1u << axis;
                info |= cases.word[mask * 10u] << 3;
            }
        }
        infos[k] = info;
        sum += uvec4(bitCount(info & 7u), info >> 3, info != 0u ? 1u : 0u, 0u);
    }
    partial[lane] = sum;
    barrier();
    for (uint d = 1u; d < 64u; d <<= 1) { // inclusive scan over the lanes
        const uvec4 add = lane >= d ? partial[lane - d] : uvec4(0u);
        barrier();
        partial[lane] += add;
        barrier();
    }
    uvec4 place = lane > 0u ? partial[lane - 1u] : uvec4(0u);
    for (uint k = 0u; k < kCellsPerInvocation; ++k) {
        const uint key = first + k;
        if (key >= count) break;
        cells.info[key] = infos[k] | place.z << 7;
        cellPlaces.place[key] = place.x | place.y << 16;
        place += uvec4(bitCount(infos[k] & 7u), infos[k] >> 3, infos[k] != 0u ? 1u : 0u, 0u);
    }
    if (lane == 63u) scan.value[push.levelOffset[1] + block] = partial[63];
}
