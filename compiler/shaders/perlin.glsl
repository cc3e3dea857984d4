// 2D improved Perlin noise and the start state's heightfield: mirrors
// compiler/builtins/src/Perlin.cpp. Every float result is `precise` so the compiler may not fuse
// multiply-adds, which keeps the GPU bit-identical to the interpreter.
// Requires random.glsl (mix32).

// Ken Perlin's reference permutation comes from the noise-table buffer (common.glsl), which the
// runtime fills from voxc::perlinPermutation: one table for both sides. A constant array here
// would be materialised on every call by some drivers (llvmpipe), costing ~1000x.
int perlinPerm(int i) { return noiseTables.perlinPermutation[i & 255]; }

float perlinFade(float t) {
    precise float r = t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
    return r;
}

float perlinLerp(float t, float a, float b) {
    precise float r = a + t * (b - a);
    return r;
}

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
    precise float u = perlinFade(xf);
    precise float v = perlinFade(yf);
    int aa = perlinPerm(perlinPerm(X) + Y);
    int ab = perlinPerm(perlinPerm(X) + Y + 1);
    int ba = perlinPerm(perlinPerm(X + 1) + Y);
    int bb = perlinPerm(perlinPerm(X + 1) + Y + 1);
    precise float x1 = perlinLerp(u, perlinGradient(aa, xf, yf), perlinGradient(ba, xf - 1.0, yf));
    precise float x2 = perlinLerp(u, perlinGradient(ab, xf, yf - 1.0), perlinGradient(bb, xf - 1.0, yf - 1.0));
    precise float r = perlinLerp(v, x1, x2);
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
