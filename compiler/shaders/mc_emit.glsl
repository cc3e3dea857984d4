#version 450
// GPU marching cubes, pass 4, over the active cells (mc_compact.glsl): every cell writes the
// vertices of the crossed edges it owns and its triangles at the places the scan gave them, so
// vertices come out ordered by global edge and triangles by global cell then table order, as the
// CPU mesher orders them. A triangle names a vertex by its owner cell's place plus the owner's
// crossed edges of lower axis. The arithmetic
// is the CPU mesher's, operation for operation (`precise`: no fused multiply-adds), so positions
// and normals agree bit for bit where the device rounds as IEEE 754 requires.

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 2) readonly buffer CaseTable {
    uint word[];
} cases;
layout(std430, set = 0, binding = 4) readonly buffer CellInfo {
    uint info[]; // per cell slot: counts in bits 0-6, the segment's vertices (7-11) and triangles (12-18) before it
} cells;
layout(std430, set = 0, binding = 5) readonly buffer Scan {
    uvec4 value[];
} scan;
layout(std430, set = 0, binding = 8) readonly buffer ActiveCells {
    uint slot[];
} activeCells;
layout(std430, set = 0, binding = 10) readonly buffer TileRanks {
    uint rank[]; // per tile of cells (x fastest): its rank among the active tiles, or none
} tileRanks;
layout(std430, set = 0, binding = 11) readonly buffer ActiveTiles {
    uint tile[];
} activeTiles;
layout(std430, set = 0, binding = 13) readonly buffer SegmentOrder {
    uint place[]; // per segment slot: its place in global key order
} segmentOrder;
// Seven words per vertex: position xyz and normal xyz (float bits), material.
layout(std430, set = 0, binding = 6) writeonly buffer Vertices {
    uint word[];
} vertices;
// Four words per triangle: three vertex indices, material.
layout(std430, set = 0, binding = 7) writeonly buffer Triangles {
    uint word[];
} triangles;

// The first vertex and triangle of the cell in slot `slot`: its segment's place (the sum of the
// segment's and its blocks' entries on every scan level) plus the segment's before the cell.
uvec2 place(uint slot, uint info) {
    const uint segment = segmentOrder.place[slot >> 3];
    uvec2 sum = uvec2((info >> 7) & 31u, (info >> 12) & 127u);
    for (uint level = 0u; level < push.pass.y; ++level) sum += scan.value[push.levelOffset[level] + (segment >> (10u * level))].xy;
    return sum;
}

// The slot of a grid-local cell of an active tile.
uint slotOf(ivec3 cell) {
    const ivec3 world = push.gridOrigin.xyz + cell;
    const uvec3 tile = uvec3((world >> int(kTileShift)) - push.tileFirst.xyz);
    const uvec3 n = uvec3(push.tileCount.xyz);
    const uvec3 inTile = uvec3(world & int(kTileSide - 1u));
    return tileRanks.rank[tile.x + n.x * (tile.y + n.y * tile.z)] * kTileSide * kTileSide * kTileSide + inTile.x +
           kTileSide * (inTile.y + kTileSide * inTile.z);
}

vec3 gradientAt(ivec3 p) {
    precise vec3 g = 0.5 * vec3(densityAt(p + ivec3(1, 0, 0)) - densityAt(p - ivec3(1, 0, 0)),
                                densityAt(p + ivec3(0, 1, 0)) - densityAt(p - ivec3(0, 1, 0)),
                                densityAt(p + ivec3(0, 0, 1)) - densityAt(p - ivec3(0, 0, 1)));
    return g;
}

void writeVertex(uint index, ivec3 lower, int axis) {
    ivec3 step = ivec3(0);
    step[axis] = 1;
    const ivec3 upper = lower + step;
    const float iso = push.surface.x;
    const float d0 = densityAt(lower), d1 = densityAt(upper);
    // In double, as voxc::marching_cubes::crossing: iso lies between the samples.
    const float t = clamp(float((double(iso) - double(d0)) / (double(d1) - double(d0))), push.surface.y, push.surface.z);
    precise vec3 position = vec3(push.gridOrigin.xyz + lower);
    position[axis] += t;
    precise vec3 gradient = (1.0 - t) * gradientAt(lower) + t * gradientAt(upper);
    precise float magnitude = sqrt((gradient.x * gradient.x + gradient.y * gradient.y) + gradient.z * gradient.z);
    precise vec3 normal;
    if (magnitude > 0.0 && !isinf(magnitude)) {
        normal = -gradient / magnitude;
    } else { // from the solid sample to the air one
        normal = vec3(0.0);
        normal[axis] = d0 > iso ? 1.0 : -1.0;
    }
    const uint base = index * 7u;
    vertices.word[base] = floatBitsToUint(position.x);
    vertices.word[base + 1u] = floatBitsToUint(position.y);
    vertices.word[base + 2u] = floatBitsToUint(position.z);
    vertices.word[base + 3u] = floatBitsToUint(normal.x);
    vertices.word[base + 4u] = floatBitsToUint(normal.y);
    vertices.word[base + 5u] = floatBitsToUint(normal.z);
    vertices.word[base + 6u] = materialAt(d0 > iso ? lower : upper);
}

// The most common material among the solid corners; ties go to the lowest id.
uint majorityMaterial(ivec3 cell, uint mask) {
    uint ids[8];
    uint count = 0u;
    for (uint c = 0u; c < 8u; ++c)
        if (((mask >> c) & 1u) != 0u) ids[count++] = materialAt(cell + cornerOffset(c));
    uint best = 0u, bestVotes = 0u;
    for (uint i = 0u; i < count; ++i) {
        uint votes = 0u;
        for (uint j = 0u; j < count; ++j) votes += ids[j] == ids[i] ? 1u : 0u;
        if (votes > bestVotes || (votes == bestVotes && ids[i] < best)) {
            best = ids[i];
            bestVotes = votes;
        }
    }
    return best;
}

uint caseEdge(uint mask, uint i) { return (cases.word[mask * 10u + 1u + i / 4u] >> (8u * (i % 4u))) & 0xffu; }

void main() {
    const uint index = invocationIndex(64u);
    if (index >= push.pass.z) return;
    const uint slot = activeCells.slot[index];
    const uint info = cells.info[slot];
    const ivec3 cell = segmentWorldCell(activeTiles.tile[slot >> 9], slot >> 3) - push.gridOrigin.xyz + ivec3(slot & 7u, 0, 0);
    const uvec2 first = place(slot, info);
    uint rank = 0u;
    for (int axis = 0; axis < 3; ++axis)
        if (((info >> axis) & 1u) != 0u) writeVertex(first.x + rank++, cell, axis);

    const uint triangleCount = (info >> 3) & 15u;
    if (triangleCount == 0u) return;
    const uint mask = cellCase(cell);
    const uint material = majorityMaterial(cell, mask);
    for (uint t = 0u; t < triangleCount; ++t) {
        const uint base = (first.y + t) * 4u;
        for (uint k = 0u; k < 3u; ++k) {
            // Edge e runs along axis e/4 from its lower corner (voxc::marching_cubes::edgeCorners);
            // the cell owning that corner is crossed, so its tile is active.
            const uint edge = caseEdge(mask, t * 3u + k);
            const uint axis = edge / 4u, along = edge % 4u, u = (axis + 1u) % 3u, v = (axis + 2u) % 3u;
            const uint owner = slotOf(cell + cornerOffset((along & 1u) << u | (along >> 1) << v));
            const uint ownerInfo = cells.info[owner];
            triangles.word[base + k] = place(owner, ownerInfo).x + bitCount(ownerInfo & ((1u << axis) - 1u));
        }
        triangles.word[base + 3u] = material;
    }
}
