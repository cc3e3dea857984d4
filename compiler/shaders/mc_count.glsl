#version 450
// GPU marching cubes, pass 1: one invocation per segment of an active tile (mc_common.glsl), in
// global key order: the case of each of its cells (bit c: corner c solid), eight bytes in two
// words, and the segment's totals of (vertices, triangles, active cells), level 0 of the scan
// (mc_scan.glsl). A cell has a vertex per crossed edge it owns (those leaving its minimum corner)
// and the case table's triangles; mc_compact.glsl derives the same from the cases. The segment's
// cells read four rows of 9 samples, read first into bits, inside the grid four samples to a
// fetch. Two words a segment, where a word per cell was written before: lavapipe stores to a
// storage buffer one lane at a time, so stores are the cost.

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 18) writeonly buffer SegmentCases {
    uvec2 cases[]; // per segment, in global key order: byte i the case of the segment's cell i
} segmentCases;
layout(std430, set = 0, binding = 5) writeonly buffer Scan {
    uvec4 value[]; // levels at push.levelOffset[level]: vertices, triangles, active cells
} scan;

// The four sample rows a row of cells reads, at (y, z), (y + 1, z), (y, z + 1), (y + 1, z + 1):
// corners 0-1, 2-3, 4-5 and 6-7 of its cells.
const ivec2 kRowOffset[4] = ivec2[4](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 1));

// Row r of the segment's samples, x from range.x to range.y: bit i is the solid bit at range.x + i.
uint rowBits(ivec3 row, ivec2 range, uint r) {
    const ivec3 first = ivec3(range.x, row.yz + kRowOffset[r]);
    // A tile of the grid's inside: its 8 samples are two reads, the ninth is the next tile's.
    if (range.x >= 0 && range.y - range.x == int(kTileSide) && first.y < push.gridSize.y && first.z < push.gridSize.z &&
        first.y >= 0 && first.z >= 0) {
        const uint at = voxelAddress(first) / 4u;
        const bvec4 low = solidQuad(quadTexel(at)), high = solidQuad(quadTexel(at + 1u));
        return (low.x ? 1u : 0u) | (low.y ? 2u : 0u) | (low.z ? 4u : 0u) | (low.w ? 8u : 0u) | (high.x ? 16u : 0u) |
               (high.y ? 32u : 0u) | (high.z ? 64u : 0u) | (high.w ? 128u : 0u) | (solidAt(first + ivec3(8, 0, 0)) ? 256u : 0u);
    }
    uint bits = 0u;
    for (int x = range.x; x <= range.y; ++x)
        if (solidAt(ivec3(x, first.yz))) bits |= 1u << uint(x - range.x);
    return bits;
}

void main() {
    const uint index = invocationIndex(64u);
    if (index >= push.pass.z) return;
    const uint segment = segmentSlot(index);
    const ivec3 world = segmentWorldCell(activeTile(segment >> 6), segment);
    const ivec2 range = segmentCells(world);
    const ivec3 row = world - push.gridOrigin.xyz;
    const uint rows[4] = uint[4](rowBits(row, range, 0u), rowBits(row, range, 1u), rowBits(row, range, 2u), rowBits(row, range, 3u));
    uvec3 sum = uvec3(0u);
    uvec2 cases = uvec2(0u);
    for (int x = range.x; x < range.y; ++x) {
        const uint i = uint(x - range.x);
        uint mask = 0u;
        for (uint r = 0u; r < 4u; ++r) mask |= ((rows[r] >> i) & 3u) << (2u * r);
        const uint edges = ownedEdges(mask), triangles = caseWord(mask * 10u);
        sum += uvec3(bitCount(edges), triangles, edges != 0u || triangles != 0u ? 1u : 0u);
        if (i < 4u)
            cases.x |= mask << (8u * i);
        else
            cases.y |= mask << (8u * (i - 4u));
    }
    segmentCases.cases[index] = cases;
    scan.value[push.levelOffset[0] + index] = uvec4(sum, 0u);
}
