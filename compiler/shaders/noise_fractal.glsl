// Fractals, domain warps and curl over perlin3: mirrors compiler/builtins/src/functions/Fractal.cpp.
// Requires noise_common.glsl, noise_permutation.glsl and noise_perlin3.glsl.

// kind 0: fbm (sum of n), 1: turbulence (sum of |n|), 2: ridged (see voxc::noise::ridged).
float noiseOctaveSum(vec3 p, int octaves, float lacunarity, float gain, uint seed, int kind) {
    precise float sum = 0.0;
    precise float amplitude = 1.0;
    precise float frequency = 1.0;
    precise float weight = 1.0;
    int count = min(max(octaves, 1), 16);
    for (int k = 0; k < count; ++k) {
        precise vec3 q = p * frequency;
        float n = noisePerlin3(q, noiseSubstream(seed, uint(k)));
        precise float term;
        if (kind == 0) {
            term = n;
        } else if (kind == 1) {
            term = abs(n);
        } else {
            precise float s = 1.0 - abs(n);
            s = s * s;
            s = s * weight;
            weight = min(max(s * 2.0, 0.0), 1.0);
            term = s;
        }
        precise float weighted = amplitude * term;
        sum = k == 0 ? weighted : sum + weighted; // not 0 + term, which a driver may fold to term
        amplitude = amplitude * gain;
        frequency = frequency * lacunarity;
    }
    return sum;
}

float noiseFbm(vec3 p, int octaves, float lacunarity, float gain, int seed) {
    return noiseOctaveSum(p, octaves, lacunarity, gain, uint(seed), 0);
}
float noiseTurbulence(vec3 p, int octaves, float lacunarity, float gain, int seed) {
    return noiseOctaveSum(p, octaves, lacunarity, gain, uint(seed), 1);
}
float noiseRidged(vec3 p, int octaves, float lacunarity, float gain, int seed) {
    return noiseOctaveSum(p, octaves, lacunarity, gain, uint(seed), 2);
}

vec3 noiseWarp(vec3 p, float amount, int seedBits) {
    uint seed = uint(seedBits);
    float wx = noiseOctaveSum(p, 4, 2.0, 0.5, noiseSubstream(seed, 101u), 0);
    float wy = noiseOctaveSum(p, 4, 2.0, 0.5, noiseSubstream(seed, 102u), 0);
    float wz = noiseOctaveSum(p, 4, 2.0, 0.5, noiseSubstream(seed, 103u), 0);
    precise vec3 r = vec3(p.x + amount * wx, p.y + amount * wy, p.z + amount * wz);
    return r;
}

vec3 noiseCurl3(vec3 p, int seedBits) {
    uint seed = uint(seedBits);
    uint s1 = noiseSubstream(seed, 201u);
    uint s2 = noiseSubstream(seed, 202u);
    uint s3 = noiseSubstream(seed, 203u);
    const float e = 0.00390625;
    const float inv = 128.0;
    precise vec3 px = vec3(p.x + e, p.y, p.z);
    precise vec3 mx = vec3(p.x - e, p.y, p.z);
    precise vec3 py = vec3(p.x, p.y + e, p.z);
    precise vec3 my = vec3(p.x, p.y - e, p.z);
    precise vec3 pz = vec3(p.x, p.y, p.z + e);
    precise vec3 mz = vec3(p.x, p.y, p.z - e);
    precise float d3dy = (noisePerlin3(py, s3) - noisePerlin3(my, s3)) * inv;
    precise float d2dz = (noisePerlin3(pz, s2) - noisePerlin3(mz, s2)) * inv;
    precise float d1dz = (noisePerlin3(pz, s1) - noisePerlin3(mz, s1)) * inv;
    precise float d3dx = (noisePerlin3(px, s3) - noisePerlin3(mx, s3)) * inv;
    precise float d2dx = (noisePerlin3(px, s2) - noisePerlin3(mx, s2)) * inv;
    precise float d1dy = (noisePerlin3(py, s1) - noisePerlin3(my, s1)) * inv;
    precise vec3 r = vec3(d3dy - d2dz, d1dz - d3dx, d2dx - d1dy);
    return r;
}

// Layer k of Mathisen's Eq 3.11 with T_pre of Eq 3.12 (see docs/functions.md).
float noiseWarpedLayer(vec3 q, float k, float invOnePlusK, float warpLow, float warpHigh, uint seed) {
    precise float w = k * warpHigh + warpLow * invOnePlusK;
    float ox = noisePerlin3(q + vec3(50.0), seed);
    float oy = noisePerlin3(q + vec3(150.0), seed);
    float oz = noisePerlin3(q + vec3(250.0), seed);
    precise vec3 t = vec3(q.x + w * ox, q.y + w * oy, q.z + w * oz);
    return noisePerlin3(t, seed);
}

float noiseWarpedFbm(vec3 p, float roughness, float warpLow, float warpHigh, int seedBits) {
    uint seed = uint(seedBits);
    precise float a = exp2(-(1.0 - roughness));
    precise float sum = 0.0;
    precise float amplitude = 1.0;
    sum = sum + amplitude * noiseWarpedLayer(p, 0.0, 1.0, warpLow, warpHigh, seed);
    amplitude = amplitude * a;
    sum = sum + amplitude * noiseWarpedLayer(p * 2.0, 1.0, 0.5, warpLow, warpHigh, seed);
    amplitude = amplitude * a;
    sum = sum + amplitude * noiseWarpedLayer(p * 4.0, 2.0, 0.333333343, warpLow, warpHigh, seed);
    amplitude = amplitude * a;
    sum = sum + amplitude * noiseWarpedLayer(p * 8.0, 3.0, 0.25, warpLow, warpHigh, seed);
    amplitude = amplitude * a;
    sum = sum + amplitude * noiseWarpedLayer(p * 16.0, 4.0, 0.2, warpLow, warpHigh, seed);
    return sum;
}

float noiseWarpedFbm(vec3 p, int seed) { return noiseWarpedFbm(p, 0.0, 1.0, 0.5, seed); }
