#version 450
// Evaporation (terrain::evaporate): d = d·keep, keep = 1 − K_e·dt (the drain: 1 − 0.9).
#include "erosion_common.glsl"

void main() {
    int i = cellOfInvocation();
    if (i < 0) return;
    precise float kept = load(kWater, i) * push.values.x;
    store(kWater, i, kept);
}
