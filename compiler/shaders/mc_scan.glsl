#version 450
// GPU marching cubes, pass 2: exclusive prefix sums of (vertices, triangles, active cells) in
// global cell order; a cell is active when it owns a vertex or has a triangle. Each workgroup
// scans a block of 1024 elements of level push.pass.w and writes the block's total to the next
// level; the host runs the levels in turn, behind a pipeline barrier each (a workgroup barrier
// orders nothing between workgroups), until one block holds the level. An element's place is
// then the sum of its block's entries over all levels. Level 0 reads the cells' counts and keeps
// each cell's place within its block in 32-bit words (a block holds at most 3 * 1023 vertices,
// 12 * 1023 triangles and 1023 active cells before a cell): vertices and triangles in cellPlaces,
// the active index above the counts in cellInfo. So a 256^3 grid's buffers fit lavapipe's
// 128 MiB binding limit; the levels above are uvec4, scanned in place.

layout(local_size_x = 256) in;

layout(std430, set = 0, binding = 4) buffer CellInfo {
    uint info[]; // as mc_count.glsl writes it; level 0 adds the active index at bit 7
} cells;
layout(std430, set = 0, binding = 5) buffer Scan {
    uvec4 value[]; // levels 1 and up at push.levelOffset[level]: vertices, triangles, active cells
} scan;
layout(std430, set = 0, binding = 8) writeonly buffer CellPlace {
    uint place[]; // vertices before the cell in its block | triangles before it << 16
} cellPlaces;

uvec4 load(uint i) {
    if (push.pass.w != 0u) return scan.value[push.levelOffset[push.pass.w] + i];
    const uint info = cells.info[i];
    return uvec4(bitCount(info & 7u), info >> 3, info != 0u ? 1u : 0u, 0u);
}

void store(uint i, uvec4 place) {
    if (push.pass.w != 0u) {
        scan.value[push.levelOffset[push.pass.w] + i] = place;
    } else {
        cellPlaces.place[i] = place.x | place.y << 16;
        cells.info[i] |= place.z << 7;
    }
}

shared uvec4 partial[256];

void main() {
    const uint block = gl_WorkGroupID.y * push.pass.x + gl_WorkGroupID.x;
    const uint count = push.pass.z;
    if (block * 1024u >= count) return; // the whole workgroup
    const uint lane = gl_LocalInvocationID.x;
    const uint first = block * 1024u + lane * 4u;
    uvec4 own[4];
    uvec4 sum = uvec4(0u);
    for (uint k = 0u; k < 4u; ++k) {
        const uvec4 v = first + k < count ? load(first + k) : uvec4(0u);
        own[k] = sum;
        sum += v;
    }
    partial[lane] = sum;
    barrier();
    for (uint d = 1u; d < 256u; d <<= 1) { // inclusive scan over the lanes
        const uvec4 add = lane >= d ? partial[lane - d] : uvec4(0u);
        barrier();
        partial[lane] += add;
        barrier();
    }
    const uvec4 before = lane > 0u ? partial[lane - 1u] : uvec4(0u);
    for (uint k = 0u; k < 4u; ++k)
        if (first + k < count) store(first + k, own[k] + before);
    if (lane == 255u) scan.value[push.levelOffset[push.pass.w + 1u] + block] = partial[255];
}
