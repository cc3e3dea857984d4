#version 450
// GPU marching cubes, pass 1: one invocation per segment of an active tile (mc_common.glsl), in
// global key order. Per cell: the crossed edges it owns (those leaving its minimum corner, one
// vertex each) and its triangle count from the case table, with the vertices and triangles of
// the segment's cells before it; then the segment's totals of (vertices, triangles, active
// cells), level 0 of the scan (mc_scan.glsl). The segment's cells read four rows of 9 samples,
// read first into bits, inside the grid four samples to a read (lavapipe reads a storage buffer
// one lane at a time, so reads are the cost).

layout(local_size_x = 64) in;

// Per cell slot. Bits 0-2: owned crossed edges by axis; bits 3-6: triangle count; bits 7-11: the
// segment's vertices before the cell; bits 12-18: its triangles before the cell (at most 3 * 7
// and 12 * 7); bits 19-26: its case.
layout(std430, set = 0, binding = 4) writeonly buffer CellInfo {
    uint info[];
} cells;
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
    const uint firstSlot = segment * kTileSide - uint(row.x); // slot of grid-local x
    const uint rows[4] = uint[4](rowBits(row, range, 0u), rowBits(row, range, 1u), rowBits(row, range, 2u), rowBits(row, range, 3u));
    uvec3 sum = uvec3(0u);
    for (int x = range.x; x < range.y; ++x) {
        const uint i = uint(x - range.x);
        uint mask = 0u;
        for (uint r = 0u; r < 4u; ++r) mask |= ((rows[r] >> i) & 3u) << (2u * r);
        const bool lowerSolid = (mask & 1u) != 0u;
        uint info = 0u;
        for (uint axis = 0u; axis < 3u; ++axis)
            if (lowerSolid != (((mask >> (1u << axis)) & 1u) != 0u)) info |= 1u << axis;
        info |= caseWord(mask * 10u) << 3;
        cells.info[firstSlot + uint(x)] = info | sum.x << 7 | sum.y << 12 | mask << 19;
        sum += uvec3(bitCount(info & 7u), info >> 3, info != 0u ? 1u : 0u);
    }
    scan.value[push.levelOffset[0] + index] = uvec4(sum, 0u);
}
