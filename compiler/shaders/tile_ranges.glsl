#version 450
// voxc runtime kernel "tile_ranges": recomputes the exact density range of every tile whose
// flag in TileDirty is set (after a start stage, or where a sweep wrote), so the next sweep
// classifies tiles on tight ranges. One invocation per tile id (tiles.glsl); a workgroup per
// tile would cost more in workgroup overhead (llvmpipe) than the tile's reads, and workgroups of
// 8 (one llvmpipe batch) spread the tiles over its threads more evenly than 64 did. Only voxels
// inside the grid count, since windows never read the padding (their occupancy bits stay clear).
// The same reads set the tile's occupancy bits (tiles.glsl).

#include "common.glsl"

layout(local_size_x = 8, local_size_y = 1, local_size_z = 1) in;

#include "tiles.glsl"

void main() {
    uint id = gl_GlobalInvocationID.x;
    if (id >= uint(push.chunkCount.x * push.chunkCount.y * push.chunkCount.z * tilesPerChunk())) return;
    ivec3 tile = tileOfId(id);
    int index = tileIndex(tile);
    if (tileDirty.flag[index] == 0u) return;
    ivec3 tileLow = tile * tileSize() - push.gridOrigin.xyz; // grid-local
    ivec3 low = max(tileLow, ivec3(0)) - tileLow;             // tile-local, the in-grid part
    ivec3 high = min(tileLow + tileSize(), push.gridSize.xyz) - tileLow;
    bool occupancy = occupancyTracked();
    uint lo = 0xffffffffu;
    uint hi = 0u;
    uint word = 0u; // occupancy rows gathered for the word they fill
    // A tile lies inside one chunk: its voxels' addresses step by 1, chunkSize and chunkSize^2.
    int chunkSize = push.gridOrigin.w;
    int lowAddress = voxelAddress(tileLow + low);
    for (int z = 0; z < tileSize(); ++z) {
        for (int y = 0; y < tileSize(); ++y) {
            uint row = 0u;
            if (z >= low.z && z < high.z && y >= low.y && y < high.y) {
                int address = lowAddress + chunkSize * ((y - low.y) + chunkSize * (z - low.z));
                for (int x = low.x; x < high.x; ++x, ++address) {
                    float density = voxels.density[address];
                    uint key = densityKey(density);
                    lo = min(lo, key);
                    hi = max(hi, key);
                    row |= uint(occupied(density)) << x;
                }
            }
            if (!occupancy) continue;
            ivec2 bit = occupancyBit(index, ivec3(0, y, z));
            word |= row << bit.y;
            if (bit.y + tileSize() == 32) {
                tileOccupancy.bits[bit.x] = word;
                word = 0u;
            }
        }
    }
    tileRanges.key[2 * index] = lo;
    tileRanges.key[2 * index + 1] = hi;
    tileDirty.flag[index] = 0u;
}
