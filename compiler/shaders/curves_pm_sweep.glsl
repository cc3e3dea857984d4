#version 450
// Perona-Malik sweep, second half: at a set cell off Omega_N, N_i + (sum_j c_ij (N_j - N_i)) / 6
// from the source half (push.size.w) into the other, over set in-box neighbours in neighbour
// order, c_ij = g(clamp((1 - u_i.u_j) * 0.5, 0, 1)), g(x) = 1 / (1 + q*q), q = x / k (push.value.x)
// (curves::peronaMalikSweeps). Other cells never change, and both halves hold them.

layout(local_size_x = 64) in;

<<CURVES_SOLVE_COMMON>>

layout(std430, set = 0, binding = 0) readonly buffer Flags { uint flags[]; }; // bit 0 set, bit 1 fixed
layout(std430, set = 0, binding = 1) buffer Normals { float normals[]; };      // two halves, xyz per cell
layout(std430, set = 0, binding = 2) readonly buffer Units { float units[]; };   // xyz per cell

void main() {
    const ivec3 p = dispatchedCell();
    if (p.x < 0) return;
    const uint i = cellIndex(p);
    if (flags[i] != 1u) return; // unset, or fixed
    const uint source = uint(push.size.w) * cellCount() * 3u, target = (1u - uint(push.size.w)) * cellCount() * 3u;
    const vec3 ni = vec3(normals[source + i * 3u], normals[source + i * 3u + 1u], normals[source + i * 3u + 2u]);
    const vec3 ui = vec3(units[i * 3u], units[i * 3u + 1u], units[i * 3u + 2u]);
    precise float ax = 0.0, ay = 0.0, az = 0.0;
    for (int d = 0; d < 6; ++d) {
        const ivec3 q = p + kNeighbours[d];
        if (!inBox(q)) continue;
        const uint j = cellIndex(q);
        if ((flags[j] & 1u) == 0u) continue;
        precise float cosine = (ui.x * units[j * 3u] + ui.y * units[j * 3u + 1u]) + ui.z * units[j * 3u + 2u];
        precise float x = clamp((1.0 - cosine) * 0.5, 0.0, 1.0);
        precise float q2 = x / push.value.x;
        precise float c = 1.0 / (1.0 + q2 * q2);
        ax += c * (normals[source + j * 3u] - ni.x);
        ay += c * (normals[source + j * 3u + 1u] - ni.y);
        az += c * (normals[source + j * 3u + 2u] - ni.z);
    }
    precise float rx = ni.x + ax / 6.0, ry = ni.y + ay / 6.0, rz = ni.z + az / 6.0;
    normals[target + i * 3u] = rx, normals[target + i * 3u + 1u] = ry, normals[target + i * 3u + 2u] = rz;
}
