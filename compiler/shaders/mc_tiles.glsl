#version 450
// GPU marching cubes, pass 0: one invocation per world-aligned 8^3 tile of voxels (the tiles of
// cells and one more per axis) that the host left unknown records on which sides of iso the
// voxels of eight regions of the tile lie: the whole tile, its low x, y and z faces, the three edges where two of those faces
// meet, and its low corner. The cells of a tile read its voxels and the low faces, edges and
// corner of the tiles after it, so the host decides from these bits alone, exactly, which tiles
// of cells the surface crosses (GpuMesher.cpp), and the later passes visit only those. Tiles
// lie inside one chunk (chunks are at least 8 wide and aligned to their size), so a tile inside
// the grid is read four samples at a time along its rows; a tile wholly outside reads as the
// outside (density 0) without a read. The host fills the states in first: where the grid's tile
// ranges put a tile on one side of iso it writes that tile's state, and lists the others, which
// alone are read here: an invocation per listed tile, so that no lane waits on a neighbour's
// reads (lavapipe runs a pass's every branch under a lane mask).

layout(local_size_x = 64) in;

// Bits 0-7: the regions holding a solid voxel; bits 8-15: those holding an air voxel.
layout(std430, set = 0, binding = 2) buffer TileStates {
    uint state[];
} tiles;

// The indices of the tiles to read, as the host listed them.
layout(set = 0, binding = 10) uniform usamplerBuffer unknownTileTexels;

const uint kWhole = 1u, kLowX = 2u, kLowY = 4u, kLowZ = 8u, kEdgeXY = 16u, kEdgeXZ = 32u, kEdgeYZ = 64u, kCorner = 128u;

// Regions holding every voxel of row (y, z) of a tile, and those holding its x = 0 voxel alone.
uint rowRegions(uint y, uint z) {
    return kWhole | (y == 0u ? kLowY : 0u) | (z == 0u ? kLowZ : 0u) | (y == 0u && z == 0u ? kEdgeYZ : 0u);
}
uint firstVoxelRegions(uint y, uint z) {
    return kLowX | (y == 0u ? kEdgeXY : 0u) | (z == 0u ? kEdgeXZ : 0u) | (y == 0u && z == 0u ? kCorner : 0u);
}

void main() {
    const uint item = invocationIndex(64u);
    if (item >= push.pass.y) return;
    const uint index = texelFetch(unknownTileTexels, int(item)).x;
    const uvec3 n = uvec3(push.tileCount.xyz) + 1u;
    const ivec3 tile = push.tileFirst.xyz + ivec3(tileCoordinates(index, n));
    const ivec3 first = (tile << kTileShift) - push.gridOrigin.xyz; // grid-local voxel
    const ivec3 last = first + int(kTileSide) - 1;
    uint solid = 0u, air = 0u;
    if (all(greaterThanEqual(first, ivec3(0))) && all(lessThan(last, push.gridSize.xyz))) {
        const uint size = 1u << uint(push.gridOrigin.w);
        const uint base = voxelAddress(first) / 4u; // x is a multiple of 8 within the chunk
        for (uint z = 0u; z < kTileSide; ++z)
            for (uint y = 0u; y < kTileSide; ++y) {
                const uint row = base + (y + z * size) * (size / 4u);
                const bvec4 low = solidQuad(quadTexel(row)), high = solidQuad(quadTexel(row + 1u));
                const uint regions = rowRegions(y, z);
                if (any(low) || any(high)) solid |= regions;
                if (!all(low) || !all(high)) air |= regions;
                if (low.x)
                    solid |= firstVoxelRegions(y, z);
                else
                    air |= firstVoxelRegions(y, z);
            }
    } else if (any(lessThan(last, ivec3(0))) || any(greaterThanEqual(first, push.gridSize.xyz))) {
        if (0.0 > push.surface.x)
            solid = 0xffu;
        else
            air = 0xffu;
    } else { // across the grid's border: one sample at a time, the outside reading 0
        for (uint z = 0u; z < kTileSide; ++z)
            for (uint y = 0u; y < kTileSide; ++y)
                for (uint x = 0u; x < kTileSide; ++x) {
                    const uint regions = rowRegions(y, z) | (x == 0u ? firstVoxelRegions(y, z) : 0u);
                    if (solidAt(first + ivec3(x, y, z)))
                        solid |= regions;
                    else
                        air |= regions;
                }
    }
    tiles.state[index] = solid | air << 8;
}
