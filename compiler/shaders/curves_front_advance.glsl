#version 450
// A front propagation's step between layers, one invocation: the next front becomes the current
// one (its count, its half, the expand pass's groups), the layer advances.

layout(local_size_x = 1) in;

#include "curves_solve_common.glsl"
#include "curves_front_common.glsl"

void setCell(uint cell, ivec3 p, int layer) {}

void main() {
    const uint count = control.nextCount;
    if (count > 0u) control.lastLayer = control.layer;
    control.count = count;
    control.nextCount = 0u;
    control.currentHalf = 1u - control.currentHalf;
    control.layer += 1;
    const uint groups = (count + 63u) / 64u;
    control.groups[0] = min(groups, 65535u);
    control.groups[1] = (groups + 65534u) / 65535u;
    control.groups[2] = 1u;
}
