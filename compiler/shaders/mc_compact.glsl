#version 450
// GPU marching cubes, pass 3: the active cells (those that own a vertex or have a triangle), in
// global key order, into a list of the counted length, so that the emit pass runs over them
// alone (lavapipe executes a shader's every branch under a lane mask, so an invocation that
// returns early still costs the whole body). One invocation per segment, in global key order:
// the segment's place from the scan plus the counts before each cell give the cell's first
// vertex and triangle, which go into the list with the cell, and, for a cell owning vertices,
// over its count (so that a triangle finds its vertices with one read); each vertex is listed
// with its owner and axis.

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 4) writeonly buffer CellInfo {
    uint info[]; // per cell slot, as mc_count.glsl writes it; then its owned edges | first vertex << 3
} cells;
// Read as mc_count.glsl wrote them (binding 4), rewritten here for cells owning vertices.
layout(set = 0, binding = 14) uniform usamplerBuffer cellInfoTexels;
layout(set = 0, binding = 15) uniform usamplerBuffer scanTexels; // mc_scan.glsl's levels
layout(std430, set = 0, binding = 8) writeonly buffer ActiveCells {
    uvec4 cell[]; // slot, first vertex, first triangle, the count's word
} activeCells;
layout(std430, set = 0, binding = 13) writeonly buffer VertexEdges {
    uint edge[]; // per vertex: its owner cell's slot | axis << 30 (slots are below 2^30)
} vertexEdges;

void main() {
    const uint index = invocationIndex(64u);
    if (index >= push.pass.z) return;
    uvec3 place = uvec3(0u);
    for (uint level = 0u; level < push.pass.y; ++level)
        place += texelFetch(scanTexels, int(push.levelOffset[level] + (index >> (10u * level)))).xyz;
    const uint segment = segmentSlot(index);
    const ivec3 world = segmentWorldCell(activeTile(segment >> 6), segment);
    const ivec2 range = segmentCells(world);
    const uint firstSlot = segment * kTileSide - uint(world.x - push.gridOrigin.x);
    for (int x = range.x; x < range.y; ++x) {
        const uint slot = firstSlot + uint(x);
        const uint info = texelFetch(cellInfoTexels, int(slot)).x;
        if ((info & 0x7fu) == 0u) continue;
        const uint firstVertex = place.x + ((info >> 7) & 31u);
        activeCells.cell[place.z++] = uvec4(slot, firstVertex, place.y + ((info >> 12) & 127u), info);
        if ((info & 7u) == 0u) continue;
        cells.info[slot] = (info & 7u) | firstVertex << 3;
        uint vertex = firstVertex;
        for (uint axis = 0u; axis < 3u; ++axis)
            if (((info >> axis) & 1u) != 0u) vertexEdges.edge[vertex++] = slot | axis << 30;
    }
}
