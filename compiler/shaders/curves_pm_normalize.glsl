#version 450
// Perona-Malik sweep, first half: the unit normals u = N / |N| of the source half (push.size.w),
// |N| = sqrt((x*x + y*y) + z*z), 0 where |N| < 1e-6 (curves::normalizeField).

layout(local_size_x = 64) in;

#include "curves_solve_common.glsl"
#include "curves_pm_common.glsl"

void main() {
    const ivec3 p = dispatchedCell();
    if (p.x < 0) return;
    const uint i = cellIndex(p);
    const vec3 n = loadNormal(push.size.w, i);
    precise float magnitude = sqrt((n.x * n.x + n.y * n.y) + n.z * n.z);
    if (!(magnitude >= 1e-6)) {
        units[i * 3u] = 0.0, units[i * 3u + 1u] = 0.0, units[i * 3u + 2u] = 0.0;
        return;
    }
    precise float ux = n.x / magnitude, uy = n.y / magnitude, uz = n.z / magnitude;
    units[i * 3u] = ux, units[i * 3u + 1u] = uy, units[i * 3u + 2u] = uz;
}
