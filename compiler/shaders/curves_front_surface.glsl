#version 450
// Surface propagation, one layer: a reached cell p takes, over its neighbours x of earlier layers
// in neighbour order, the candidate S_x + s * ((n_p[a] + n_x[a]) * 0.5) (p = x + s e_a) of
// smallest |value| (tie: the smaller value; push.size.w = 1: the smallest value), as
// curves::propagateSurface.

layout(local_size_x = 64) in;

#include "curves_solve_common.glsl"
#include "curves_front_common.glsl"

layout(std430, set = 0, binding = 3) buffer Distance { float surfaceDistance[]; };
layout(std430, set = 0, binding = 4) readonly buffer Normals { float normals[]; }; // unit, xyz per cell

void setCell(uint cell, ivec3 p, int layer) {
    float best = 0.0;
    bool found = false;
    for (int d = 0; d < 6; ++d) {
        const ivec3 q = p + kNeighbours[d];
        if (!inBox(q)) continue;
        const uint x = cellIndex(q);
        if (!earlierLayer(x, layer)) continue;
        const int axis = kNeighbours[d].x != 0 ? 0 : kNeighbours[d].y != 0 ? 1 : 2;
        const bool positive = kNeighbours[d][axis] < 0; // p - x along the axis
        precise float change = (normals[cell * 3u + uint(axis)] + normals[x * 3u + uint(axis)]) * 0.5;
        precise float candidate = surfaceDistance[x] + (positive ? change : -change);
        const bool better = push.size.w == 1
                                ? candidate < best
                                : abs(candidate) < abs(best) || (abs(candidate) == abs(best) && candidate < best);
        if (!found || better) best = candidate, found = true;
    }
    surfaceDistance[cell] = best;
}

void main() { expandFront(); }
