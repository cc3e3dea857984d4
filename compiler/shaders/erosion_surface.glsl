#version 450
// surface = b (+ d with water), b = base + S_h, so every neighbour read is one load
// (terrain's computeSurface).
#include "erosion_common.glsl"

void main() {
    int i = cellOfInvocation();
    if (i < 0) return;
    precise float b = load(kBase, i) + load(push.grid.z, i);
    precise float withWater = b + load(kWater, i);
    store(kSurface, i, push.mode.x != 0 ? withWater : b);
}
