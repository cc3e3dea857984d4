#version 450
// GPU marching cubes, pass 5, over the active cells (mc_compact.glsl): every cell writes its
// triangles at the place the scan gave it, so triangles come out ordered by global cell then
// table order, as the CPU mesher orders them. A triangle names a vertex by its owner cell's
// first vertex plus the owner's crossed edges of lower axis.

layout(local_size_x = 64) in;

// Per cell slot owning vertices: its owned edges | first vertex << 3 (mc_compact.glsl).
layout(set = 0, binding = 14) uniform usamplerBuffer cellInfoTexels;
// Per active cell: slot, first vertex, first triangle, mc_count.glsl's word.
layout(set = 0, binding = 16) uniform usamplerBuffer activeCellTexels;
// Per tile of cells (x fastest): its rank among the active tiles, or none.
layout(set = 0, binding = 10) uniform usamplerBuffer tileRankTexels;
// A texel per triangle: three vertex indices, material.
layout(set = 0, binding = 7, rgba32ui) uniform writeonly uimageBuffer triangles;

// The slot of a grid-local cell of an active tile.
uint slotOf(ivec3 cell) {
    const ivec3 world = push.gridOrigin.xyz + cell;
    const uvec3 tile = uvec3((world >> int(kTileShift)) - push.tileFirst.xyz);
    const uvec3 n = uvec3(push.tileCount.xyz);
    const uvec3 inTile = uvec3(world & int(kTileSide - 1u));
    return texelFetch(tileRankTexels, int(tile.x + n.x * (tile.y + n.y * tile.z))).x * kTileSide * kTileSide * kTileSide + inTile.x +
           kTileSide * (inTile.y + kTileSide * inTile.z);
}

// The most common material among the solid corners; ties go to the lowest id. Each round takes
// the id of the lowest solid corner not yet counted and counts the corners with it, so there are
// as many rounds as distinct ids (lavapipe runs a loop until its last lane is done: mostly one
// round, where counting every corner's votes took 64 steps). Indexed by corner alone, so that
// the compiler keeps the ids in registers (lavapipe spills an array indexed by a running count
// to memory, one lane at a time).
uint majorityMaterial(ivec3 cell, uint mask) {
    if (!kHasMaterials) return 0u;
    uint ids[8];
    for (uint c = 0u; c < 8u; ++c) ids[c] = ((mask >> c) & 1u) != 0u ? materialAt(cell + cornerOffset(c)) : 0u;
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

uint caseEdge(uint mask, uint i) { return (caseWord(mask * 10u + 1u + i / 4u) >> (8u * (i % 4u))) & 0xffu; }

void main() {
    const uint index = invocationIndex(64u);
    if (index >= push.pass.z) return;
    const uvec4 entry = texelFetch(activeCellTexels, int(index));
    const uint slot = entry.x, info = entry.w;
    const ivec3 cell = cellOfSlot(activeTile(slot >> 9), slot);
    const uint triangleCount = (info >> 3) & 15u;
    const uint mask = (info >> 19) & 0xffu;
    const uint material = majorityMaterial(cell, mask);
    for (uint t = 0u; t < triangleCount; ++t) {
        uvec4 triangle = uvec4(0u, 0u, 0u, material);
        for (uint k = 0u; k < 3u; ++k) {
            // Edge e runs along axis e/4 from its lower corner (voxc::marching_cubes::edgeCorners);
            // the cell owning that corner is crossed, so its tile is active.
            const uint edge = caseEdge(mask, t * 3u + k);
            const uint axis = edge / 4u, along = edge % 4u, u = (axis + 1u) % 3u, v = (axis + 2u) % 3u;
            const uint owner = texelFetch(cellInfoTexels, int(slotOf(cell + cornerOffset((along & 1u) << u | (along >> 1) << v)))).x;
            triangle[k] = (owner >> 3) + bitCount(owner & ((1u << axis) - 1u));
        }
        imageStore(triangles, int(entry.z + t), triangle);
    }
}
