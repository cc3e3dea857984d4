#version 450
// <<COMPONENTS>>
#include "mg_common.glsl"
// Multigrid pass: the max over free cells of level push.fine (the finest) and every component of
// |0 - sum_j w_j (u_j - u_i)|, the quantity the schedule stops on. Max is order-free, so the
// workgroup maximum and an atomic max of the bits (non-negative floats order as their bits) give
// the host's value exactly.

layout(local_size_x = 64) in;

shared uint best[64];

void main() {
    const ivec4 l = push.fine;
    const ivec3 p = ivec3(gl_GlobalInvocationID);
    float worst = 0.0;
    if (p.x < l.x && p.y < l.y && p.z < l.z) {
        const uint i = cellIndex(l, p);
        if (fixedCell[i] == 0u)
            for (int c = 0; c < COMPONENTS; ++c) worst = max(worst, abs(residualAt(c, p, i, 0.0)));
    }
    const uint lane = gl_LocalInvocationID.x;
    best[lane] = floatBitsToUint(worst);
    barrier();
    for (uint stride = 32u; stride > 0u; stride >>= 1) {
        if (lane < stride) best[lane] = max(best[lane], best[lane + stride]);
        barrier();
    }
    if (lane == 0u) atomicMax(maxResidualBits, best[0]);
}
