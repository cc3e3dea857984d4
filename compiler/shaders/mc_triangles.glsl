#version 450
// GPU marching cubes, pass 3, over the active cells (listed by the host from mc_count.glsl's
// cases, GpuMesher.cpp): every cell writes its triangles at the place the host gave it, so
// triangles come out ordered by global cell then table order, as the CPU mesher orders them. A
// triangle names a vertex by its owner cell's first vertex plus the owner's crossed edges of
// lower axis.

layout(local_size_x = 64) in;

// Per cell slot owning vertices: its owned edges | first vertex << 3 (the host's list).
layout(set = 0, binding = 9) uniform usamplerBuffer cellInfoTexels;
// Per active cell: slot, first vertex, first triangle, owned edges | triangle count << 3 | case << 19.
layout(set = 0, binding = 10) uniform usamplerBuffer activeCellTexels;
// Per case a texel of two words: its (at most 15) triangles' edge indices, eight 4-bit ones to a
// word, so that a cell's triangles cost one fetch.
layout(set = 0, binding = 2) uniform usamplerBuffer caseTexels;
// A texel per triangle: three vertex indices, material.
layout(set = 0, binding = 5, rgba32ui) uniform writeonly uimageBuffer triangles;

// Per axis, for the cell (offset 0) and the next one (offset 1): the parts of a tile's index
// among the tiles of cells and of a cell's place in its tile, which add up over the axes.
uint tileParts[3][2], placeParts[3][2];

void openCorners(ivec3 cell) {
    const uvec3 n = uvec3(push.tileCount.xyz);
    for (int o = 0; o < 2; ++o) {
        const ivec3 world = push.gridOrigin.xyz + cell + o;
        const uvec3 tile = uvec3((world >> int(kTileShift)) - push.tileFirst.xyz);
        const uvec3 inTile = uvec3(world & int(kTileSide - 1u));
        tileParts[0][o] = tile.x;
        tileParts[1][o] = n.x * tile.y;
        tileParts[2][o] = n.x * n.y * tile.z;
        placeParts[0][o] = inTile.x;
        placeParts[1][o] = kTileSide * inTile.y;
        placeParts[2][o] = kTileSide * kTileSide * inTile.z;
    }
}

// What the host recorded this time at the slot of the cell at corner c (a constant) of the
// cell: its owned edges | first vertex << 3 where it owns any. A corner cell in no active tile or
// past the tiles of cells owns none of the cell's crossed edges, so its word (whatever an earlier
// mesh left there) is never used; its fetch is kept inside the buffer.
uint cornerOwner(const uint c) {
    const uint x = c & 1u, y = (c >> 1) & 1u, z = c >> 2;
    const uint tile = tileParts[0][x] + tileParts[1][y] + tileParts[2][z];
    const uint tiles = uint(push.tileCount.x * push.tileCount.y * push.tileCount.z);
    return texelFetch(cellInfoTexels, int(min(tile, tiles - 1u) * kTileCells + placeParts[0][x] + placeParts[1][y] + placeParts[2][z])).x;
}

// The most common material among the solid corners; ties go to the lowest id. Each round takes
// the id of the lowest solid corner not yet counted and counts the corners with it, so there are
// as many rounds as distinct ids (lavapipe runs a loop until its last lane is done: mostly one
// round, where counting every corner's votes took 64 steps). Indexed by corner alone, so that
// the compiler keeps the ids in registers (lavapipe spills an array indexed by a running count
// to memory, one lane at a time).
uint majorityMaterial(ivec3 cell, uint mask) {
    if (!kHasMaterials) return 0u;
    uint parts[3][2];
    bool inside[3][2];
    for (int o = 0; o < 2; ++o) {
        parts[0][o] = axisPart(0, cell.x + o, inside[0][o]);
        parts[1][o] = axisPart(1, cell.y + o, inside[1][o]);
        parts[2][o] = axisPart(2, cell.z + o, inside[2][o]);
    }
    uint ids[8];
    for (uint c = 0u; c < 8u; ++c) {
        const uint x = c & 1u, y = (c >> 1) & 1u, z = c >> 2;
        const bool read = ((mask >> c) & 1u) != 0u && inside[0][x] && inside[1][y] && inside[2][z];
        ids[c] = read ? texelFetch(materialTexels, int(parts[0][x] + parts[1][y] + parts[2][z])).x & 0xffu : 0u; // as materialAt
    }
    uint best = 0u, bestVotes = 0u;
    for (uint uncounted = mask & 0xffu; uncounted != 0u;) {
        uint id = 0u;
        for (int c = 7; c >= 0; --c) id = ((uncounted >> c) & 1u) != 0u ? ids[c] : id; // the lowest one's
        uint same = 0u;
        for (uint c = 0u; c < 8u; ++c) same |= ((uncounted >> c) & 1u) != 0u && ids[c] == id ? 1u << c : 0u;
        const uint votes = uint(bitCount(same));
        if (votes > bestVotes || (votes == bestVotes && id < best)) {
            best = id;
            bestVotes = votes;
        }
        uncounted &= ~same;
    }
    return best;
}

void main() {
    const uint index = invocationIndex(64u);
    if (index >= push.pass.y) return;
    const uvec4 entry = texelFetch(activeCellTexels, int(index));
    const uint slot = entry.x, info = entry.w;
    const ivec3 cell = cellOfSlot(slot);
    const uint triangleCount = (info >> 3) & 15u;
    const uint mask = (info >> 19) & 0xffu;
    const uint material = majorityMaterial(cell, mask);
    // The vertex on each of the cell's 12 edges where it is crossed. Edge e runs along axis e/4
    // from its lower corner (voxc::marching_cubes::edgeCorners), whose cell owns its vertex: the
    // owner's first vertex plus its crossed edges of lower axis.
    openCorners(cell);
    uint owners[7]; // the cells at corners 0-6 (corner 7 owns none of the cell's edges)
    for (uint c = 0u; c < 7u; ++c) owners[c] = cornerOwner(c);
    uint edgeVertex[12];
    for (uint e = 0u; e < 12u; ++e) {
        const uint axis = e / 4u, along = e % 4u, u = (axis + 1u) % 3u, v = (axis + 2u) % 3u;
        const uint owner = owners[(along & 1u) << u | (along >> 1) << v];
        edgeVertex[e] = (owner >> 3) + bitCount(owner & ((1u << axis) - 1u));
    }
    const uvec2 caseEdges = texelFetch(caseTexels, int(mask)).xy;
    for (uint t = 0u; t < triangleCount; ++t) {
        uvec4 triangle = uvec4(0u, 0u, 0u, material);
        for (uint k = 0u; k < 3u; ++k) {
            const uint i = t * 3u + k;
            const uint edge = ((i < 8u ? caseEdges.x : caseEdges.y) >> (4u * (i & 7u))) & 15u;
            uint vertex = edgeVertex[0];
            for (uint e = 1u; e < 12u; ++e) vertex = edge == e ? edgeVertex[e] : vertex; // constant indices
            triangle[k] = vertex;
        }
        imageStore(triangles, int(entry.z + t), triangle);
    }
}
