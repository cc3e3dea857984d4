#version 450
// GPU marching cubes, pass 2: exclusive prefix sums of (vertices, triangles) in global cell
// order. Each workgroup scans a block of 1024 elements of level push.pass.w and writes the
// block's total to the next level; the host runs the levels in turn, behind a pipeline barrier
// each (a workgroup barrier orders nothing between workgroups), until one block holds the level.
// An element's place is then the sum of its block's entries over all levels. Level 0 reads the
// cells' counts and writes each cell's place within its block, packed in one uint (a block holds
// at most 3 * 1023 vertices and 12 * 1023 triangles before a cell), so a 256^3 grid's buffers
// fit lavapipe's 128 MiB binding limit; the levels above are uvec2, scanned in place.

layout(local_size_x = 256) in;

layout(std430, set = 0, binding = 4) readonly buffer CellInfo {
    uint info[]; // as mc_count.glsl writes it
} cells;
layout(std430, set = 0, binding = 5) buffer Scan {
    uvec2 value[]; // levels 1 and up at push.levelOffset[level]
} scan;
layout(std430, set = 0, binding = 8) writeonly buffer CellPlace {
    uint place[]; // vertices before the cell in its block | triangles before it << 16
} cellPlaces;

uvec2 load(uint i) {
    if (push.pass.w != 0u) return scan.value[push.levelOffset[push.pass.w] + i];
    const uint info = cells.info[i];
    return uvec2(bitCount(info & 7u), info >> 3);
}

void store(uint i, uvec2 place) {
    if (push.pass.w != 0u)
        scan.value[push.levelOffset[push.pass.w] + i] = place;
    else
        cellPlaces.place[i] = place.x | place.y << 16;
}

shared uvec2 partial[256];

void main() {
    const uint block = gl_WorkGroupID.y * push.pass.x + gl_WorkGroupID.x;
    const uint count = push.pass.z;
    if (block * 1024u >= count) return; // the whole workgroup
    const uint lane = gl_LocalInvocationID.x;
    const uint first = block * 1024u + lane * 4u;
    uvec2 own[4];
    uvec2 sum = uvec2(0u);
    for (uint k = 0u; k < 4u; ++k) {
        const uvec2 v = first + k < count ? load(first + k) : uvec2(0u);
        own[k] = sum;
        sum += v;
    }
    partial[lane] = sum;
    barrier();
    for (uint d = 1u; d < 256u; d <<= 1) { // inclusive scan over the lanes
        const uvec2 add = lane >= d ? partial[lane - d] : uvec2(0u);
        barrier();
        partial[lane] += add;
        barrier();
    }
    const uvec2 before = lane > 0u ? partial[lane - 1u] : uvec2(0u);
    for (uint k = 0u; k < 4u; ++k)
        if (first + k < count) store(first + k, own[k] + before);
    if (lane == 255u) scan.value[push.levelOffset[push.pass.w + 1u] + block] = partial[255];
}
