// A front propagation, one BFS layer per dispatch over a compacted front list (spec A3.6;
// curves::propagateSurface, curves::propagateMaterial). The pass that includes this defines
// setCell, the value of a newly reached cell from its neighbours set in earlier layers. A cell is
// claimed once (its layer word goes from -1 to the layer by compare-and-swap); its value reads only
// cells of earlier layers, which no invocation of this dispatch writes, so the order of the front
// list, and of the appends to the next one, changes no value.

layout(std430, set = 0, binding = 0) buffer Layers { int layerOf[]; }; // -1: not reached yet
layout(std430, set = 0, binding = 1) buffer Fronts { uint front[]; };  // two halves of cellCount() each
// The schedule's state; the host uploads it with the first front (GpuCurves.cpp writes kFront*).
layout(std430, set = 0, binding = 2) buffer FrontControl {
    uint nextCount;    // cells appended to the next front so far
    uint count;        // cells of the current front; 0: done (the count the runner reads back)
    uint groups[3];    // the expand pass's indirect dispatch
    int layer;         // the layer the current front's neighbours join
    uint currentHalf;  // the half of `front` the current front is in
    int lastLayer;     // the last layer that reached a cell
} control;

// A cell of layer `layer` reached from the front: value it (its neighbours q with
// 0 <= layerOf[q] < layer are final).
void setCell(uint cell, ivec3 p, int layer);

bool earlierLayer(uint cell, int layer) {
    const int l = layerOf[cell];
    return l >= 0 && l < layer;
}

// The expand pass: one invocation per cell of the current front (the indirect groups' x count is
// at most 65535, rows of them along y).
void expandFront() {
    const uint t = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    if (t >= control.count) return;
    const int layer = control.layer;
    const uint cell = front[control.currentHalf * cellCount() + t];
    const ivec3 p = cellOf(cell);
    for (int d = 0; d < 6; ++d) {
        const ivec3 q = p + kNeighbours[d];
        if (!inBox(q)) continue;
        const uint j = cellIndex(q);
        if (layerOf[j] != -1 || atomicCompSwap(layerOf[j], -1, layer) != -1) continue;
        setCell(j, q, layer);
        front[(1u - control.currentHalf) * cellCount() + atomicAdd(control.nextCount, 1u)] = j;
    }
}
