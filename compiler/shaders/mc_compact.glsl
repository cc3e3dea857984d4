#version 450
// GPU marching cubes, pass 3: the active cells (those that own a vertex or have a triangle), in
// global key order, into a list of the counted length, so that the emit pass runs over them
// alone (lavapipe executes a shader's every branch under a lane mask, so an invocation that
// returns early still costs the whole body). One invocation per segment, in global key order.

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 4) readonly buffer CellInfo {
    uint info[]; // per cell slot, counts in bits 0-6
} cells;
layout(std430, set = 0, binding = 5) readonly buffer Scan {
    uvec4 value[];
} scan;
layout(std430, set = 0, binding = 8) writeonly buffer ActiveCells {
    uint slot[];
} activeCells;
layout(std430, set = 0, binding = 11) readonly buffer ActiveTiles {
    uint tile[];
} activeTiles;
layout(std430, set = 0, binding = 12) readonly buffer Segments {
    uint slot[];
} segments;

void main() {
    const uint index = invocationIndex(64u);
    if (index >= push.pass.z) return;
    uint place = 0u;
    for (uint level = 0u; level < push.pass.y; ++level) place += scan.value[push.levelOffset[level] + (index >> (10u * level))].z;
    const uint segment = segments.slot[index];
    const ivec3 world = segmentWorldCell(activeTiles.tile[segment >> 6], segment);
    const ivec2 range = segmentCells(world);
    const uint firstSlot = segment * kTileSide - uint(world.x - push.gridOrigin.x);
    for (int x = range.x; x < range.y; ++x) {
        const uint slot = firstSlot + uint(x);
        if ((cells.info[slot] & 0x7fu) != 0u) activeCells.slot[place++] = slot;
    }
}
