#version 450
// GPU marching cubes, pass 0 (only when uniform chunks are skipped): one workgroup per world
// chunk holding cells decides whether every voxel its cells read (the chunk's cells [begin, end]
// inclusive, as voxc::surface_nets::cellsAreUniform scans them) lies on one side of iso.

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 3) writeonly buffer ChunkFlags {
    uint uniformChunk[]; // 1: no cell of the chunk is crossed
} flags;

shared uint sawSolid;
shared uint sawAir;

void main() {
    const uint chunk = gl_WorkGroupID.y * push.pass.x + gl_WorkGroupID.x;
    if (chunk >= push.pass.z) return; // the whole workgroup, so no barrier is left waiting
    if (gl_LocalInvocationID.x == 0u) {
        sawSolid = 0u;
        sawAir = 0u;
    }
    barrier();
    const uvec3 counts = uvec3(push.cellChunkCount.xyz);
    const ivec3 world = push.cellChunkFirst.xyz + ivec3(chunk % counts.x, (chunk / counts.x) % counts.y, chunk / (counts.x * counts.y));
    const ivec3 chunkFirst = (world << push.gridOrigin.w) - push.gridOrigin.xyz;
    const ivec3 begin = max(chunkFirst, ivec3(-1));
    const ivec3 end = min(chunkFirst + (1 << push.gridOrigin.w), push.gridSize.xyz);
    const uvec3 extent = uvec3(end - begin + 1);
    const uint voxelsRead = extent.x * extent.y * extent.z;
    // Each invocation collects the sides of its own voxels, then takes one atomic per side.
    bool solid = false, air = false;
    for (uint i = gl_LocalInvocationID.x; i < voxelsRead && !(solid && air); i += gl_WorkGroupSize.x) {
        const ivec3 p = begin + ivec3(i % extent.x, (i / extent.x) % extent.y, i / (extent.x * extent.y));
        if (solidAt(p))
            solid = true;
        else
            air = true;
    }
    if (solid) atomicOr(sawSolid, 1u);
    if (air) atomicOr(sawAir, 1u);
    barrier();
    if (gl_LocalInvocationID.x == 0u) flags.uniformChunk[chunk] = sawSolid == 0u || sawAir == 0u ? 1u : 0u;
}
