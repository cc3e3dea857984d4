#version 450
// Material vote, one layer: a reached cell sums its earlier-layer neighbours' confidences per
// material (slots in order of first appearance, neighbour order) and in total, and takes the
// largest sum's material (tie: the lowest id) with confidence sum / total, as
// curves::propagateMaterial.

layout(local_size_x = 64) in;

#include "curves_solve_common.glsl"
#include "curves_front_common.glsl"

layout(std430, set = 0, binding = 3) buffer Materials { uint material[]; };
layout(std430, set = 0, binding = 4) buffer Confidence { float confidence[]; };

void setCell(uint cell, ivec3 p, int layer) {
    uint ids[6];
    float weights[6];
    int distinct = 0;
    precise float total = 0.0;
    for (int d = 0; d < 6; ++d) {
        const ivec3 q = p + kNeighbours[d];
        if (!inBox(q)) continue;
        const uint j = cellIndex(q);
        if (!earlierLayer(j, layer)) continue;
        const float conf = confidence[j];
        total += conf;
        int slot = 0;
        while (slot < distinct && ids[slot] != material[j]) ++slot;
        if (slot == distinct) {
            ids[distinct] = material[j];
            weights[distinct] = 0.0;
            ++distinct;
        }
        precise float w = weights[slot] + conf;
        weights[slot] = w;
    }
    int best = 0;
    for (int s = 1; s < distinct; ++s)
        if (weights[s] > weights[best] || (weights[s] == weights[best] && ids[s] < ids[best])) best = s;
    material[cell] = ids[best];
    precise float c = weights[best] / total;
    confidence[cell] = c;
}

void main() { expandFront(); }
