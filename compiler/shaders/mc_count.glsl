#version 450
// GPU marching cubes, pass 1: one invocation per active tile (mc_common.glsl): the case of each of
// its cells (bit c: corner c solid), a segment's eight bytes in two words at the segment's index
// in global key order, which the host reads in that order to list the active cells, the
// vertices and their places (GpuMesher.cpp). The tile's cells read its 9 x 9 rows of 9 samples
// along x, each row read once, into bits: a plane of rows at z, then the plane at z + 1, whose
// rows pair with the plane before into the cases of the segments at z (an invocation per segment
// read each of its four rows anew: 12 fetches a segment where this makes 3.8). The rows are named
// variables, not arrays: lavapipe keeps an array indexed in a loop in memory, one lane at a time.

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 9) writeonly buffer SegmentCases {
    uvec2 cases[]; // per segment, in global key order: byte i the case of the segment's cell i
} segmentCases;

// Per active tile by rank, from the host: its index among the tiles of cells, then where its
// segments go: the segment at (y, z) within the tile has index x + y * y' + z * z' (unsigned, so x
// may wrap below 0). Only the segments the host lists (rows of cells of the grid) are written.
layout(set = 0, binding = 6) uniform usamplerBuffer countTileTexels;

// The tile's x: per-axis address parts (axisPart) of its rows' three fetches, which of its 9
// samples along x lie in the grid, and the shift from its first cell to the first cell of the
// grid (segmentCells).
uint xParts[3];
bool xInside[9];
uint xShift;

// The row at address parts `yz` (its y and z): bit i is the solid bit of the sample at the
// tile's low x + xShift + i. It is read from the tile's low x (a multiple of 8 in the world, so
// inside one chunk and a multiple of 4 in the buffer) as two texels of four samples and the next
// tile's first sample, with no branch (lavapipe runs both sides): a fetch with no sample in the
// grid reads texel 0, and a four-sample fetch with any sample in the grid reads within that
// sample's chunk.
uint readRow(uint yz, bool rowInside) {
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
    return bits >> xShift;
}

// A row's pairs of neighbouring bits, (bit i, bit i + 1) at bits 8 i of x for i < 4 and at bits
// 8 (i - 4) of y for the others: a cell's corners along x in its byte of the segment's words.
uvec2 rowPairs(uint bits) {
    const uvec4 lo = (uvec4(bits) << uvec4(0u, 7u, 14u, 21u)) & uvec4(0x3u, 0x300u, 0x30000u, 0x3000000u);
    const uvec4 hi = (uvec4(bits >> 4) << uvec4(0u, 7u, 14u, 21u)) & uvec4(0x3u, 0x300u, 0x30000u, 0x3000000u);
    return uvec2(lo.x | lo.y | lo.z | lo.w, hi.x | hi.y | hi.z | hi.w);
}

// The y parts of rows 0-8 of the tile, then a plane of their rows' pairs at one z.
#define Y_PART(i) bool yInside##i; const uint yPart##i = axisPart(1, row.y + i, yInside##i);
#define PLANE(p)                                                                                                             \
    const uvec2 p##0 = rowPairs(readRow(yPart0 + zPart, yInside0 && zInside));                                               \
    const uvec2 p##1 = rowPairs(readRow(yPart1 + zPart, yInside1 && zInside));                                               \
    const uvec2 p##2 = rowPairs(readRow(yPart2 + zPart, yInside2 && zInside));                                               \
    const uvec2 p##3 = rowPairs(readRow(yPart3 + zPart, yInside3 && zInside));                                               \
    const uvec2 p##4 = rowPairs(readRow(yPart4 + zPart, yInside4 && zInside));                                               \
    const uvec2 p##5 = rowPairs(readRow(yPart5 + zPart, yInside5 && zInside));                                               \
    const uvec2 p##6 = rowPairs(readRow(yPart6 + zPart, yInside6 && zInside));                                               \
    const uvec2 p##7 = rowPairs(readRow(yPart7 + zPart, yInside7 && zInside));                                               \
    const uvec2 p##8 = rowPairs(readRow(yPart8 + zPart, yInside8 && zInside));
// Corners 0-1 from row (y, z), 2-3 from (y + 1, z), 4-5 from (y, z + 1), 6-7 from (y + 1, z + 1).
#define CASES(i, j)                                                                                                      \
    if (zListed && row.y + i >= -1 && row.y + i < push.gridSize.y)                                                       \
        segmentCases.cases[first + uint(i) * place.y] = (below##i | below##j << 2 | above##i << 4 | above##j << 6) & keep;

void main() {
    const uint rank = invocationIndex(64u);
    if (rank >= push.pass.y) return;
    const uvec4 tile = texelFetch(countTileTexels, int(rank));
    const uvec3 place = tile.yzw;
    const ivec3 world = segmentWorldCell(tile.x, 0u);
    const ivec2 range = segmentCells(world);
    const ivec3 row = world - push.gridOrigin.xyz;
    bool unused;
    for (int i = 0; i < 9; ++i) xInside[i] = row.x + i >= 0 && row.x + i < push.gridSize.x;
    for (int i = 0; i < 3; ++i) xParts[i] = axisPart(0, row.x + 4 * i, unused);
    xShift = uint(range.x - row.x);
    // The bytes of the cells past the grid's x read 0.
    const uint cells = uint(range.y - range.x); // 1 to 8: the tile overlaps the cells along x
    const uvec2 keep = uvec2(cells >= 4u ? 0xffffffffu : (1u << (8u * cells)) - 1u,
                             cells >= 8u ? 0xffffffffu : cells <= 4u ? 0u : (1u << (8u * (cells - 4u))) - 1u);
    Y_PART(0) Y_PART(1) Y_PART(2) Y_PART(3) Y_PART(4) Y_PART(5) Y_PART(6) Y_PART(7) Y_PART(8)
    bool zInside;
    uint zPart = axisPart(2, row.z, zInside);
    PLANE(start)
    uvec2 below0 = start0, below1 = start1, below2 = start2, below3 = start3, below4 = start4, below5 = start5,
          below6 = start6, below7 = start7, below8 = start8;
    for (uint z = 0u; z < kTileSide; ++z) {
        zPart = axisPart(2, row.z + int(z) + 1, zInside);
        PLANE(above)
        const bool zListed = row.z + int(z) >= -1 && row.z + int(z) < push.gridSize.z;
        const uint first = place.x + z * place.z;
        CASES(0, 1) CASES(1, 2) CASES(2, 3) CASES(3, 4) CASES(4, 5) CASES(5, 6) CASES(6, 7) CASES(7, 8)
        below0 = above0; below1 = above1; below2 = above2; below3 = above3; below4 = above4;
        below5 = above5; below6 = above6; below7 = above7; below8 = above8;
    }
}
