#version 450
// GPU marching cubes, pass 2: exclusive prefix sums of (vertices, triangles, active cells) over
// the totals of the level below (level 0 holds those of mc_count.glsl's segments, level 1 those
// of level 0's 1024-element blocks). Each workgroup scans a block of 1024 elements of level push.pass.w in place and writes the
// block's total to the next level; the host runs the levels in turn, behind a pipeline barrier
// each (a workgroup barrier orders nothing between workgroups), until one block holds the level.
// A segment's place is then the sum of its own and its blocks' entries on every level.

layout(local_size_x = 256) in;

layout(std430, set = 0, binding = 5) writeonly buffer Scan {
    uvec4 value[]; // level l at push.levelOffset[l]
} scan;
// The same levels, read as texels (each element is read before the one invocation that writes it
// writes it).
layout(set = 0, binding = 15) uniform usamplerBuffer scanTexels;

shared uvec4 partial[256];

void main() {
    const uint block = gl_WorkGroupID.y * push.pass.x + gl_WorkGroupID.x;
    const uint count = push.pass.z;
    if (block * 1024u >= count) return; // the whole workgroup
    const uint lane = gl_LocalInvocationID.x;
    const uint base = push.levelOffset[push.pass.w];
    const uint first = block * 1024u + lane * 4u;
    uvec4 own[4];
    uvec4 sum = uvec4(0u);
    for (uint k = 0u; k < 4u; ++k) {
        const uvec4 v = first + k < count ? texelFetch(scanTexels, int(base + first + k)) : uvec4(0u);
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
        if (first + k < count) scan.value[base + first + k] = own[k] + before;
    if (lane == 255u) scan.value[push.levelOffset[push.pass.w + 1u] + block] = partial[255];
}
