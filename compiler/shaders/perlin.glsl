// 2D improved Perlin noise and the start state's heightfield: mirrors
// compiler/builtins/src/Perlin.cpp. Every float result is `precise` so the compiler may not fuse
// multiply-adds, which keeps the GPU bit-identical to the interpreter.
// Requires common.glsl and random.glsl; shares the lattice helpers of noise_common.glsl
// (the permutation comes from the noise-table buffer, one table for both sides).

#include "noise_common.glsl"

// Eight 2D gradient directions: the four diagonals and the four axes.
float perlinGradient(int hash, float x, float y) {
    precise float r;
    switch (hash & 7) {
    case 0: r = x + y; break;
    case 1: r = -x + y; break;
    case 2: r = x - y; break;
    case 3: r = -x - y; break;
    case 4: r = x; break;
    case 5: r = -x; break;
    case 6: r = y; break;
    default: r = -y; break;
    }
    return r;
}

float perlin2(float x, float y) {
    precise float fx = floor(x);
    precise float fy = floor(y);
    int X = int(fx) & 255;
    int Y = int(fy) & 255;
    precise float xf = x - fx;
    precise float yf = y - fy;
    precise float u = noiseFade(xf);
    precise float v = noiseFade(yf);
    int aa = noisePerm(noisePerm(X) + Y);
    int ab = noisePerm(noisePerm(X) + Y + 1);
    int ba = noisePerm(noisePerm(X + 1) + Y);
    int bb = noisePerm(noisePerm(X + 1) + Y + 1);
    precise float x1 = noiseLerp(u, perlinGradient(aa, xf, yf), perlinGradient(ba, xf - 1.0, yf));
    precise float x2 = noiseLerp(u, perlinGradient(ab, xf, yf - 1.0), perlinGradient(bb, xf - 1.0, yf - 1.0));
    precise float r = noiseLerp(v, x1, x2);
    return r;
}

float heightfieldHeight(int worldX, int worldZ, uint seed, float base, float amplitude0, float frequency0,
                        int octaves, float lacunarity, float gain) {
    precise float height = base;
    precise float amplitude = amplitude0;
    precise float frequency = frequency0;
    for (int octave = 0; octave < octaves; ++octave) {
        uint h = mix32(seed ^ mix32(uint(octave) + 0x68u));
        float offsetX = float(h & 1023u);
        float offsetZ = float((h >> 10) & 1023u);
        precise float sx = float(worldX) * frequency + offsetX;
        precise float sz = float(worldZ) * frequency + offsetZ;
        precise float n = perlin2(sx, sz);
        height = height + amplitude * n;
        amplitude = amplitude * gain;
        frequency = frequency * lacunarity;
    }
    return height;
}
