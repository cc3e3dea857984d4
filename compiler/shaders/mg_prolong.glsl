#version 450
// <<COMPONENTS>>
#include "mg_common.glsl"
// Multigrid pass: trilinear cell-centred interpolation of level push.coarse at every free cell
// of level push.fine, along x, then y, then z: on a halved axis weights 3/4 (own parent) and 1/4
// (the next parent towards the child, clamped at the box), on a kept axis 1 and 0. Added to u
// when push.halved.w is 1 (a V-cycle's correction), written when 0 (full multigrid's start).

layout(local_size_x = 64) in;

int otherParent(int v, int n, int halved) {
    return halved != 0 ? clamp((v & 1) != 0 ? v / 2 + 1 : v / 2 - 1, 0, n - 1) : v;
}

void main() {
    const ivec4 fl = push.fine, cl = push.coarse;
    const ivec3 p = ivec3(gl_GlobalInvocationID);
    if (p.x >= fl.x || p.y >= fl.y || p.z >= fl.z) return;
    const uint i = cellIndex(fl, p);
    if (fixedCell[i] != 0u) return;
    const ivec3 h = push.halved.xyz;
    const ivec3 parent = p >> h;
    const int xs[2] = int[2](parent.x, otherParent(p.x, cl.x, h.x));
    const int ys[2] = int[2](parent.y, otherParent(p.y, cl.y, h.y));
    const int zs[2] = int[2](parent.z, otherParent(p.z, cl.z, h.z));
    const vec3 near = vec3(h.x != 0 ? 0.75 : 1.0, h.y != 0 ? 0.75 : 1.0, h.z != 0 ? 0.75 : 1.0);
    const vec3 far = vec3(1.0) - near; // exact: 1/4 or 0
    for (int c = 0; c < COMPONENTS; ++c) {
        precise float alongY[2];
        for (int k = 0; k < 2; ++k) {
            precise float alongX[2];
            for (int j = 0; j < 2; ++j)
                alongX[j] = near.x * loadU(c, cellIndex(cl, ivec3(xs[0], ys[j], zs[k]))) +
                            far.x * loadU(c, cellIndex(cl, ivec3(xs[1], ys[j], zs[k])));
            alongY[k] = near.y * alongX[0] + far.y * alongX[1];
        }
        precise float v = near.z * alongY[0] + far.z * alongY[1];
        if (push.halved.w != 0) {
            precise float sum = loadU(c, i) + v;
            storeU(c, i, sum);
        } else {
            storeU(c, i, v);
        }
    }
}
