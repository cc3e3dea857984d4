#version 450
// The noise displacement of every cell: alpha * warped_fbm(f0 * p, beta, 0, 0, seed) at the cell's
// grid-local voxel p = origin + cell, 0 where alpha is 0 (curves::solveScene's D), through the
// builtin's own GLSL (noise_fractal.glsl), so it agrees with the host within warped_fbm's
// tolerance (its exp2 is not exact on every device).

layout(local_size_x = 64) in;

#include "curves_solve_common.glsl"

layout(std430, set = 0, binding = 0) readonly buffer Amplitude { float amplitude[]; };
layout(std430, set = 0, binding = 1) readonly buffer Roughness { float roughness[]; };
// Perlin's permutation (voxc::perlinPermutation), as common.glsl declares it for field kernels.
layout(std430, set = 0, binding = 2) readonly buffer NoiseTables { int perlinPermutation[]; } noiseTables;
layout(std430, set = 0, binding = 3) writeonly buffer Displacement { float displacement[]; };

#include "random.glsl"
#include "noise_common.glsl"
#include "noise_permutation.glsl"
#include "noise_perlin3.glsl"
#include "noise_fractal.glsl"

void main() {
    const ivec3 p = dispatchedCell();
    if (p.x < 0) return;
    const uint i = cellIndex(p);
    const float alpha = amplitude[i];
    precise float d = 0.0;
    if (alpha != 0.0) {
        precise vec3 q = vec3(push.origin.xyz + p) * push.value.x;
        d = alpha * noiseWarpedFbm(q, roughness[i], 0.0, 0.0, push.extra.x);
    }
    displacement[i] = d;
}
