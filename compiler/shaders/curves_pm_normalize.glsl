#version 450
// Perona-Malik sweep, first half: the unit normals u = N / |N| of the source half (push.size.w),
// |N| = sqrt((x*x + y*y) + z*z), 0 where |N| < 1e-6 (curves::normalizeField).

layout(local_size_x = 64) in;

<<CURVES_SOLVE_COMMON>>

layout(std430, set = 0, binding = 0) readonly buffer Flags { uint flags[]; }; // bit 0 set, bit 1 fixed
layout(std430, set = 0, binding = 1) buffer Normals { float normals[]; };      // two halves, xyz per cell
layout(std430, set = 0, binding = 2) buffer Units { float units[]; };          // xyz per cell

void main() {
    const ivec3 p = dispatchedCell();
    if (p.x < 0) return;
    const uint i = cellIndex(p);
    const uint n = (uint(push.size.w) * cellCount() + i) * 3u;
    const float x = normals[n], y = normals[n + 1u], z = normals[n + 2u];
    precise float magnitude = sqrt((x * x + y * y) + z * z);
    if (!(magnitude >= 1e-6)) {
        units[i * 3u] = 0.0, units[i * 3u + 1u] = 0.0, units[i * 3u + 2u] = 0.0;
        return;
    }
    precise float ux = x / magnitude, uy = y / magnitude, uz = z / magnitude;
    units[i * 3u] = ux, units[i * 3u + 1u] = uy, units[i * 3u + 2u] = uz;
}
