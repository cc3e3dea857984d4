#version 450
// Perona-Malik sweep, second half: at a set cell off Omega_N, N_i + (sum_j c_ij (N_j - N_i)) / 6
// from the source half (push.size.w) into the other, over set in-box neighbours in neighbour
// order, c_ij = g(clamp((1 - u_i.u_j) * 0.5, 0, 1)), g(x) = 1 / (1 + q*q), q = x / k (push.value.x)
// (curves::peronaMalikSweeps). Other cells never change, and both halves hold them.

layout(local_size_x = 64) in;

#include "curves_solve_common.glsl"
#include "curves_pm_common.glsl"

void main() {
    const ivec3 p = dispatchedCell();
    if (p.x < 0) return;
    const uint i = cellIndex(p);
    if (flags[i] != 1u) return; // unset, or fixed
    const int source = push.size.w;
    const vec3 ni = loadNormal(source, i);
    const vec3 ui = loadUnit(i);
    precise float ax = 0.0, ay = 0.0, az = 0.0;
    for (int d = 0; d < 6; ++d) {
        const ivec3 q = p + kNeighbours[d];
        if (!inBox(q)) continue;
        const uint j = cellIndex(q);
        if ((flags[j] & 1u) == 0u) continue;
        const vec3 uj = loadUnit(j), nj = loadNormal(source, j);
        precise float cosine = (ui.x * uj.x + ui.y * uj.y) + ui.z * uj.z;
        precise float x = clamp((1.0 - cosine) * 0.5, 0.0, 1.0);
        precise float q2 = x / push.value.x;
        precise float c = 1.0 / (1.0 + q2 * q2);
        ax += c * (nj.x - ni.x);
        ay += c * (nj.y - ni.y);
        az += c * (nj.z - ni.z);
    }
    precise float rx = ni.x + ax / 6.0, ry = ni.y + ay / 6.0, rz = ni.z + az / 6.0;
    storeNormal(1 - source, i, vec3(rx, ry, rz));
}
