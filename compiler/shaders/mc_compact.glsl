#version 450
// GPU marching cubes, pass 3: the active cells (those that own a vertex or have a triangle), in
// global key order, into a list of the counted length, so that the emit passes run over them
// alone (lavapipe executes a shader's every branch under a lane mask, so an invocation that
// returns early still costs the whole body). One invocation per block of segments (mc_common.glsl),
// in global key order: the block's place from the scan plus the counts of its cells before each
// (from their cases, as mc_count.glsl counted them) give the cell's first vertex and triangle,
// which go into the list with the cell; a cell owning vertices records its first one at its slot
// (so that a triangle finds its vertices with one read), and each vertex is listed with its owner
// and axis. Every write is a texel store: lavapipe stores to a storage buffer one lane at a time.

layout(local_size_x = 64) in;

// Per cell slot owning vertices: its owned edges | first vertex << 3.
layout(set = 0, binding = 4, r32ui) uniform writeonly uimageBuffer cellInfo;
layout(set = 0, binding = 19) uniform usamplerBuffer segmentCaseTexels; // mc_count.glsl's cases
layout(set = 0, binding = 15) uniform usamplerBuffer scanTexels; // mc_scan.glsl's levels
// A texel per active cell: slot, first vertex, first triangle, and owned edges | triangle count
// << 3 | case << 19.
layout(set = 0, binding = 8, rgba32ui) uniform writeonly uimageBuffer activeCells;
// Per vertex: its owner cell's slot | axis << 30 (slots are below 2^30).
layout(set = 0, binding = 13, r32ui) uniform writeonly uimageBuffer vertexEdges;

void main() {
    const uint block = invocationIndex(64u), first = block * kBlockSegments;
    if (first >= push.pass.z) return;
    uvec3 place = uvec3(0u);
    for (uint level = 0u; level < push.pass.y; ++level)
        place += texelFetch(scanTexels, int(push.levelOffset[level] + (block >> (10u * level)))).xyz;
    for (uint index = first; index < min(first + kBlockSegments, push.pass.z); ++index) {
        const uvec2 cases = texelFetch(segmentCaseTexels, int(index)).xy;
        const uint segment = segmentSlot(index);
        const ivec3 world = segmentWorldCell(activeTile(segment >> 6), segment);
        const ivec2 range = segmentCells(world);
        const uint firstSlot = segment * kTileSide - uint(world.x - push.gridOrigin.x);
        // Bit i: the segment's cell i is active, that is neither all air nor all solid (every
        // other case has a triangle; GpuMesher.cpp checks the table), so no table read. The
        // stores then run over the active cells and owned edges alone: lavapipe runs a loop until
        // its last lane is done, and a masked store still walks every lane.
        uint activeBits = 0u;
        for (int x = range.x; x < range.y; ++x) {
            const uint i = uint(x - range.x);
            const uint mask = ((i < 4u ? cases.x : cases.y) >> (8u * (i & 3u))) & 0xffu;
            activeBits |= mask != 0u && mask != 0xffu ? 1u << i : 0u;
        }
        for (; activeBits != 0u; activeBits &= activeBits - 1u) {
            const uint i = uint(findLSB(activeBits));
            const uint mask = ((i < 4u ? cases.x : cases.y) >> (8u * (i & 3u))) & 0xffu;
            const uint edges = ownedEdges(mask), triangles = caseWord(mask * 10u);
            const uint slot = firstSlot + uint(range.x) + i;
            imageStore(activeCells, int(place.z++), uvec4(slot, place.x, place.y, edges | triangles << 3 | mask << 19));
            place.y += triangles;
            if (edges != 0u) imageStore(cellInfo, int(slot), uvec4(edges | place.x << 3));
            for (uint left = edges; left != 0u; left &= left - 1u)
                imageStore(vertexEdges, int(place.x++), uvec4(slot | uint(findLSB(left)) << 30));
        }
    }
}
