#version 450
// GPU marching cubes, pass 3, over the active cells (listed by the host from mc_count.glsl's
// cases, GpuMesher.cpp): the material of each cell's triangles, the most common among its solid
// corners, as the CPU mesher votes. The host makes the triangles themselves from its lists (the
// vertices that the cell's edges' owners numbered), while this pass and mc_vertices.glsl run.
// Only where the executor's materials are not mapped (staged, as on a discrete GPU): elsewhere
// (lavapipe, integrated GPUs) the host votes from the vertices' materials and the mapped words.

layout(local_size_x = 64) in;

// Per active cell: slot, first vertex, first triangle, owned edges | triangle count << 3 | case << 19.
layout(set = 0, binding = 7) uniform usamplerBuffer activeCellTexels;
// Per active cell: its triangles' material.
layout(set = 0, binding = 4, r32ui) uniform writeonly uimageBuffer cellMaterials;

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
    imageStore(cellMaterials, int(index), uvec4(majorityMaterial(cellOfSlot(entry.x), (entry.w >> 19) & 0xffu)));
}
