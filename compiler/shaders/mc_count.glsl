#version 450
// GPU marching cubes, pass 1: one invocation per segment of an active tile (mc_common.glsl), in
// global key order. Per cell: the crossed edges it owns (those leaving its minimum corner, one
// vertex each) and its triangle count from the case table, with the vertices and triangles of
// the segment's cells before it; then the segment's totals of (vertices, triangles, active
// cells), level 0 of the scan (mc_scan.glsl). Consecutive cells of a row share a face, so a cell
// reads the four samples of its +x face and takes the others from the cell before it (lavapipe
// reads a storage buffer one lane at a time, so reads are the cost).

layout(local_size_x = 64) in;

// Per case 10 words: the triangle count, then 36 edge indices, four bytes to a word.
layout(std430, set = 0, binding = 2) readonly buffer CaseTable {
    uint word[];
} cases;
// Per cell slot. Bits 0-2: owned crossed edges by axis; bits 3-6: triangle count; bits 7-11: the
// segment's vertices before the cell; bits 12-18: its triangles before the cell (at most 3 * 7
// and 12 * 7); bits 19-26: its case.
layout(std430, set = 0, binding = 4) writeonly buffer CellInfo {
    uint info[];
} cells;
layout(std430, set = 0, binding = 5) writeonly buffer Scan {
    uvec4 value[]; // levels at push.levelOffset[level]: vertices, triangles, active cells
} scan;
layout(std430, set = 0, binding = 11) readonly buffer ActiveTiles {
    uint tile[]; // by rank: the tile's index among the tiles of cells (x fastest)
} activeTiles;
layout(std430, set = 0, binding = 12) readonly buffer Segments {
    uint slot[]; // in global key order
} segments;

// Solid bits of the four samples of the x = p.x face of a cell at p: bit 0 at p, 1 at +y, 2 at +z, 3 at +y+z.
uint faceBits(ivec3 p) {
    return (solidAt(p) ? 1u : 0u) | (solidAt(p + ivec3(0, 1, 0)) ? 2u : 0u) | (solidAt(p + ivec3(0, 0, 1)) ? 4u : 0u) |
           (solidAt(p + ivec3(0, 1, 1)) ? 8u : 0u);
}

// Face bits at corner offsets x = 0 (corners 0, 2, 4, 6) or x = 1 (corners 1, 3, 5, 7).
uint spread(uint face) { return (face & 1u) | (face & 2u) << 1 | (face & 4u) << 2 | (face & 8u) << 3; }

void main() {
    const uint index = invocationIndex(64u);
    if (index >= push.pass.z) return;
    const uint segment = segments.slot[index];
    const ivec3 world = segmentWorldCell(activeTiles.tile[segment >> 6], segment);
    const ivec2 range = segmentCells(world);
    const ivec3 row = world - push.gridOrigin.xyz;
    const uint firstSlot = segment * kTileSide - uint(row.x); // slot of grid-local x
    uint highFace = faceBits(ivec3(range.x, row.yz));
    uvec3 sum = uvec3(0u);
    for (int x = range.x; x < range.y; ++x) {
        const uint lowFace = highFace;
        highFace = faceBits(ivec3(x + 1, row.yz));
        const uint mask = spread(lowFace) | spread(highFace) << 1;
        const bool lowerSolid = (mask & 1u) != 0u;
        uint info = 0u;
        for (uint axis = 0u; axis < 3u; ++axis)
            if (lowerSolid != (((mask >> (1u << axis)) & 1u) != 0u)) info |= 1u << axis;
        info |= cases.word[mask * 10u] << 3;
        cells.info[firstSlot + uint(x)] = info | sum.x << 7 | sum.y << 12 | mask << 19;
        sum += uvec3(bitCount(info & 7u), info >> 3, info != 0u ? 1u : 0u);
    }
    scan.value[push.levelOffset[0] + index] = uvec4(sum, 0u);
}
