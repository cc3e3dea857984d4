#version 450
// GPU marching cubes, pass 3: the active cells (those that own a vertex or have a triangle), in
// global cell order, into a list of the counted length, so that the emit pass runs over them
// alone (lavapipe executes a shader's every branch under a lane mask, so an invocation that
// returns early still costs the whole body). 16 consecutive cells per invocation, which share
// their 1024-cell scan block and so the scan levels' part of the place.

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 4) readonly buffer CellInfo {
    uint info[]; // counts in bits 0-6, the active index within the scan block above
} cells;
layout(std430, set = 0, binding = 5) readonly buffer Scan {
    uvec4 value[];
} scan;
layout(std430, set = 0, binding = 9) writeonly buffer ActiveCells {
    uint key[];
} activeCells;

const uint kCellsPerInvocation = 16u;

void main() {
    const uint first = invocationIndex(64u) * kCellsPerInvocation;
    if (first >= push.pass.z) return;
    uint blockPlace = 0u;
    for (uint level = 1u; level < push.pass.y; ++level) blockPlace += scan.value[push.levelOffset[level] + (first >> (10u * level))].z;
    const uint end = min(first + kCellsPerInvocation, push.pass.z);
    for (uint key = first; key < end; ++key) {
        const uint info = cells.info[key];
        if ((info & 0x7fu) != 0u) activeCells.key[blockPlace + (info >> 7)] = key;
    }
}
