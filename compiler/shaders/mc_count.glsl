#version 450
// GPU marching cubes, pass 1: one invocation per segment of the active tiles (mc_common.glsl), in
// global key order: the case of each of its cells (bit c: corner c solid), the segment's eight
// bytes in two words, which the host reads to list the active cells, the vertices and their
// places (GpuMesher.cpp). The segment's cells read four rows of 9 samples, read first into bits.

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 12) writeonly buffer SegmentCases {
    uvec2 cases[]; // per segment, in global key order: byte i the case of the segment's cell i
} segmentCases;

// The segment's samples: x from range.x to range.x + 8 (those past range.y are not used) in the
// four rows at (y, z), (y + 1, z), (y, z + 1), (y + 1, z + 1), corners 0-1, 2-3, 4-5 and 6-7 of
// its cells; bit i of row r is the solid bit at range.x + i. A row is read from its tile's low x
// (row.x, a multiple of 8 in the world, so inside one chunk and a multiple of 4 in the buffer) as
// two texels of four samples and the next tile's first sample, three fetches where nine were
// made, and shifted to range.x. Each fetch adds per-axis address parts (axisPart), with no branch
// (lavapipe runs both sides): a fetch with no sample in the grid reads texel 0, and a four-sample
// fetch with any sample in the grid reads within that sample's chunk.
void readRows(ivec3 row, ivec2 range, out uint rows[4]) {
    bool xInside[9], yInside[2], zInside[2], unused;
    for (int i = 0; i < 9; ++i) xInside[i] = row.x + i >= 0 && row.x + i < push.gridSize.x;
    const uint xParts[3] = uint[3](axisPart(0, row.x, unused), axisPart(0, row.x + 4, unused), axisPart(0, row.x + 8, unused));
    uint yParts[2], zParts[2];
    for (int o = 0; o < 2; ++o) {
        yParts[o] = axisPart(1, row.y + o, yInside[o]);
        zParts[o] = axisPart(2, row.z + o, zInside[o]);
    }
    const uint shift = uint(range.x - row.x);
    for (int r = 0; r < 4; ++r) {
        const int y = r & 1, z = r >> 1;
        const bool rowInside = yInside[y] && zInside[z];
        const uint yz = yParts[y] + zParts[z];
        const bvec4 low = bvec4(rowInside && xInside[0], rowInside && xInside[1], rowInside && xInside[2], rowInside && xInside[3]);
        const bvec4 high = bvec4(rowInside && xInside[4], rowInside && xInside[5], rowInside && xInside[6], rowInside && xInside[7]);
        const bool last = rowInside && xInside[8];
        // As solidAt: outside the grid and not finite read 0.
        const bvec4 lowSolid = solidQuad(mix(vec4(0.0), quadTexel(any(low) ? (xParts[0] + yz) >> 2 : 0u), low));
        const bvec4 highSolid = solidQuad(mix(vec4(0.0), quadTexel(any(high) ? (xParts[1] + yz) >> 2 : 0u), high));
        const float d = densityTexel(last ? xParts[2] + yz : 0u);
        const bool lastSolid = (last && !isnan(d) && !isinf(d) ? d : 0.0) > push.surface.x;
        const uvec4 lowBits = uvec4(lowSolid) << uvec4(0u, 1u, 2u, 3u), highBits = uvec4(highSolid) << uvec4(4u, 5u, 6u, 7u);
        const uint bits = lowBits.x | lowBits.y | lowBits.z | lowBits.w | highBits.x | highBits.y | highBits.z | highBits.w |
                          (lastSolid ? 1u << 8 : 0u);
        rows[r] = bits >> shift;
    }
}

void main() {
    const uint index = invocationIndex(64u);
    if (index >= push.pass.y) return;
    const uint segment = segmentSlot(index);
    const ivec3 world = segmentWorldCell(activeTile(segment >> 6), segment);
    const ivec2 range = segmentCells(world);
    uint rows[4];
    readRows(world - push.gridOrigin.xyz, range, rows);
    uvec2 cases = uvec2(0u);
    for (int x = range.x; x < range.y; ++x) {
        const uint i = uint(x - range.x);
        uint mask = 0u;
        for (uint r = 0u; r < 4u; ++r) mask |= ((rows[r] >> i) & 3u) << (2u * r);
        if (i < 4u)
            cases.x |= mask << (8u * i);
        else
            cases.y |= mask << (8u * (i - 4u));
    }
    segmentCases.cases[index] = cases;
}
