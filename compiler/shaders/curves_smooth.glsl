#version 450
// Binomial smoothing, one axis (push.size.w) of one pass: ((a + 2b) + c) * 0.25 from the source
// half (push.origin.w) into the other, the neighbours clamped to the box (curves::smoothBinomial).

layout(local_size_x = 64) in;

#include "curves_solve_common.glsl"

layout(std430, set = 0, binding = 0) buffer Values { float values[]; }; // two halves

void main() {
    const ivec3 p = dispatchedCell();
    if (p.x < 0) return;
    const int axis = push.size.w;
    ivec3 lo = p, hi = p;
    lo[axis] = max(lo[axis] - 1, 0);
    hi[axis] = min(hi[axis] + 1, push.size[axis] - 1);
    const uint source = uint(push.origin.w) * cellCount(), target = (1u - uint(push.origin.w)) * cellCount();
    const float a = values[source + cellIndex(lo)], b = values[source + cellIndex(p)], c = values[source + cellIndex(hi)];
    precise float r = ((a + 2.0 * b) + c) * 0.25;
    values[target + cellIndex(p)] = r;
}
