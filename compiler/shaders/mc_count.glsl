#version 450
// GPU marching cubes, pass 1: per cell, the crossed grid edges it owns (those leaving its
// minimum corner, one vertex each) and its triangle count from the case table; both feed the
// scan in global cell order, which gives every vertex and triangle its place in the mesh.

layout(local_size_x = 64) in;

// Per case 10 words: the triangle count, then 36 edge indices, four bytes to a word.
layout(std430, set = 0, binding = 2) readonly buffer CaseTable {
    uint word[];
} cases;
layout(std430, set = 0, binding = 3) readonly buffer ChunkFlags {
    uint uniformChunk[];
} flags;
// Bits 0-2: owned crossed edges by axis; bits 3 and up: triangle count.
layout(std430, set = 0, binding = 4) writeonly buffer CellInfo {
    uint info[];
} cells;

bool inUniformChunk(ivec3 cell) {
    const uvec3 chunk = uvec3(((push.gridOrigin.xyz + cell) >> push.gridOrigin.w) - push.cellChunkFirst.xyz);
    const uvec3 counts = uvec3(push.cellChunkCount.xyz);
    return flags.uniformChunk[chunk.x + counts.x * (chunk.y + counts.y * chunk.z)] != 0u;
}

void main() {
    const uint key = invocationIndex(64u);
    if (key >= push.pass.z) return;
    const ivec3 cell = cellOfKey(key);
    uint info = 0u;
    if (push.cellChunkCount.w == 0 || !inUniformChunk(cell)) {
        const uint mask = cellCase(cell);
        const bool lowerSolid = (mask & 1u) != 0u;
        for (uint axis = 0u; axis < 3u; ++axis)
            if (lowerSolid != (((mask >> (1u << axis)) & 1u) != 0u)) info |= 1u << axis;
        info |= cases.word[mask * 10u] << 3;
    }
    cells.info[key] = info;
}
