// Shared by the GPU marching-cubes passes (runtime/vulkan/src/GpuMesherPipelines.cpp inserts it
// after each pass's #version line, behind kHasMaterials: whether the executor's material buffer
// has a uint per voxel, a constant so that a grid without materials compiles their reads away):
// the push block (McPush there, field for field), the executor's voxel and
// material buffers, and reads of samples, cells and chunks exactly as the CPU mesher makes them
// (runtime/mesh/src/MarchingCubes.cpp: outside the grid and non-finite read 0, solid is > iso).

layout(push_constant, std430) uniform McPush {
    ivec4 gridOrigin;     // xyz: world coordinate of grid voxel (0,0,0); w: log2 chunk size
    ivec4 gridSize;       // xyz: voxels per axis; w: unused
    ivec4 chunkBase;      // xyz: world chunk of voxel-buffer slot 0; w: slots along x
    ivec4 tileFirst;      // xyz: first world 8^3 tile holding cells; w: voxel-buffer slots along y
    ivec4 tileCount;      // xyz: such tiles per axis (the voxel tiles: one more per axis); w: unused
    vec4 surface;         // x: iso; y, z: the crossing's clamp, margin and 1 - margin
    uvec4 pass;           // x: workgroups along x; y: items of this dispatch; zw: unused
} push;

// Densities and material ids (low byte of a uint), chunk-major at the same addresses, as uniform
// texel buffers over the executor's storage buffers: lavapipe fetches texels as vector gathers,
// where it reads a storage buffer one lane at a time behind a branch per lane (the tiles pass
// over every tile of a 256^3 grid took 46 ms of CPU time through a storage buffer, 19 ms so).
layout(set = 0, binding = 0) uniform samplerBuffer densityTexels;
layout(set = 0, binding = 1) uniform usamplerBuffer materialTexels;
// The densities again, four to a texel: a row of a chunk is contiguous, so four samples from
// x = 0 mod 4 along it are one fetch.
layout(set = 0, binding = 5) uniform samplerBuffer quadTexels;

float densityTexel(uint address) { return texelFetch(densityTexels, int(address)).x; }
vec4 quadTexel(uint quad) { return texelFetch(quadTexels, int(quad)); }

// Dispatches are at most 65535 workgroups along x, so large ones use y as well. The local size
// is a parameter: this file comes before the pass's local_size layout, where gl_WorkGroupSize
// would still read (1, 1, 1).
uint invocationIndex(uint localSize) {
    return (gl_WorkGroupID.y * push.pass.x + gl_WorkGroupID.x) * localSize + gl_LocalInvocationID.x;
}

// The coordinates (x fastest) of index `index` of a box of n.x * n.y * n.z tiles, below 2^21.
// lavapipe has no vector integer division and divides one lane at a time (three divisions a
// lane, where the passes' other work per lane is a few hundred instructions), so the quotients
// come from a float division, exact to within one for such indices, and one correction each way.
uint tileQuotient(uint a, uint b) {
    uint q = uint(float(a) / float(b));
    q -= q * b > a ? 1u : 0u;
    q += (q + 1u) * b <= a ? 1u : 0u;
    return q;
}
uvec3 tileCoordinates(uint index, uvec3 n) {
    const uint row = tileQuotient(index, n.x), z = tileQuotient(row, n.y);
    return uvec3(index - row * n.x, row - z * n.y, z);
}

bool insideGrid(ivec3 p) {
    return all(greaterThanEqual(p, ivec3(0))) && all(lessThan(p, push.gridSize.xyz));
}

// As voxc::ChunkLayout::address: the chunk table is the identity, so the slot is the table index.
uint voxelAddress(ivec3 local) {
    const int shift = push.gridOrigin.w;
    const ivec3 world = push.gridOrigin.xyz + local;
    const uvec3 entry = uvec3((world >> shift) - push.chunkBase.xyz);
    const uvec3 inside = uvec3(world & ((1 << shift) - 1));
    const uint slot = entry.x + uint(push.chunkBase.w) * (entry.y + uint(push.tileFirst.w) * entry.z);
    const uint size = 1u << uint(shift);
    return slot * size * size * size + inside.x + size * (inside.y + size * inside.z);
}

// voxelAddress is a sum of one part per axis: the part grid-local coordinate `local` along
// axis 0, 1 or 2 (a constant) adds, so that a pass reading many samples around one place computes
// each axis's few parts once. `inside`: the coordinate lies in the grid along that axis.
uint axisPart(const int axis, int local, out bool inside) {
    const int shift = push.gridOrigin.w;
    const uint size = 1u << uint(shift);
    const int world = push.gridOrigin[axis] + local;
    const uint entry = uint((world >> shift) - push.chunkBase[axis]), within = uint(world & int(size - 1u));
    inside = local >= 0 && local < push.gridSize[axis];
    const uint slotStride = axis == 0 ? 1u : axis == 1 ? uint(push.chunkBase.w) : uint(push.chunkBase.w) * uint(push.tileFirst.w);
    const uint voxelStride = axis == 0 ? 1u : axis == 1 ? size : size * size;
    return entry * slotStride * size * size * size + within * voxelStride;
}

float densityAt(ivec3 p) {
    if (!insideGrid(p)) return 0.0;
    const float d = densityTexel(voxelAddress(p));
    return isnan(d) || isinf(d) ? 0.0 : d;
}

bool solidAt(ivec3 p) { return densityAt(p) > push.surface.x; }

// solidAt for four densities: not finite reads 0.
bvec4 solidQuad(vec4 d) {
    const vec4 finite = mix(vec4(0.0), d, lessThan(abs(d), vec4(uintBitsToFloat(0x7f800000u))));
    return greaterThan(finite, vec4(push.surface.x));
}

uint materialAt(ivec3 p) {
    if (!kHasMaterials || !insideGrid(p)) return 0u;
    return texelFetch(materialTexels, int(voxelAddress(p))).x & 0xffu;
}

// Cells are named by their minimum corner, grid-local, from -1 to gridSize - 1 per axis; their
// key (x fastest) is voxc::surface_nets::CellDomain::key, the global order of the mesh.
//
// The passes after mc_tiles.glsl visit only the active tiles: world-aligned 8^3 tiles of cells
// that hold a cell the surface crosses, listed by the host in tile order (z, then y, then x) and
// ranked. A segment is the row of an active tile's cells along x at one (y, z), named by rank *
// 64 + y + 8 z within the tile; the host lists the segments in global key order (GpuMesher.cpp,
// TileLists::segments), the order of the mesh. A cell has a slot, its tile's index among the tiles of cells (x fastest)
// * 512 + its place in the tile (x fastest), so that a cell finds its neighbours' slots without
// a look-up.
const uint kTileShift = 3u;
const uint kTileSide = 1u << kTileShift;
const uint kTileCells = kTileSide * kTileSide * kTileSide;

// The first world cell of the row at (y, z) = (row & 7, (row >> 3) & 7) of the tile of cells with
// index `tile` (its low x).
ivec3 segmentWorldCell(uint tile, uint row) {
    const uvec3 n = uvec3(push.tileCount.xyz);
    const ivec3 first = push.tileFirst.xyz + ivec3(tileCoordinates(tile, n));
    return (first << kTileShift) + ivec3(0, row & 7u, (row >> 3) & 7u);
}

// The grid-local cell of a slot.
ivec3 cellOfSlot(uint slot) {
    return segmentWorldCell(slot >> 9, slot >> 3) - push.gridOrigin.xyz + ivec3(slot & 7u, 0, 0);
}

// The cells of a segment's row that are cells of the grid: grid-local x in [begin, end).
ivec2 segmentCells(ivec3 worldFirst) {
    const int x = worldFirst.x - push.gridOrigin.x;
    return ivec2(max(x, -1), min(x + int(kTileSide), push.gridSize.x));
}

// Corner c of a cell is at offset (c&1, (c>>1)&1, (c>>2)&1); bit c of a case is corner c solid.
ivec3 cornerOffset(uint corner) { return ivec3(corner & 1u, (corner >> 1) & 1u, (corner >> 2) & 1u); }
