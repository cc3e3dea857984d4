// Ken Perlin's improved noise (2002) with a seed-derived lattice translation: mirrors
// voxc::noise::perlin3 (compiler/builtins/src/functions/GradientNoise.cpp).
// Requires noise_common.glsl.

float noisePerlin3(vec3 p, uint seed) {
    precise vec3 f = floor(p);
    ivec3 offset = noiseSeedOffset(seed);
    int X = (noiseLatticeIndex(f.x) + offset.x) & 255;
    int Y = (noiseLatticeIndex(f.y) + offset.y) & 255;
    int Z = (noiseLatticeIndex(f.z) + offset.z) & 255;
    precise float x = p.x - f.x;
    precise float y = p.y - f.y;
    precise float z = p.z - f.z;
    float u = noiseFade(x);
    float v = noiseFade(y);
    float w = noiseFade(z);
    int A = noisePerm(X) + Y;
    int AA = noisePerm(A) + Z;
    int AB = noisePerm(A + 1) + Z;
    int B = noisePerm(X + 1) + Y;
    int BA = noisePerm(B) + Z;
    int BB = noisePerm(B + 1) + Z;
    precise float x1 = x - 1.0;
    precise float y1 = y - 1.0;
    precise float z1 = z - 1.0;
    float l00 = noiseLerp(u, noiseGrad(noisePerm(AA), x, y, z), noiseGrad(noisePerm(BA), x1, y, z));
    float l10 = noiseLerp(u, noiseGrad(noisePerm(AB), x, y1, z), noiseGrad(noisePerm(BB), x1, y1, z));
    float l01 = noiseLerp(u, noiseGrad(noisePerm(AA + 1), x, y, z1), noiseGrad(noisePerm(BA + 1), x1, y, z1));
    float l11 = noiseLerp(u, noiseGrad(noisePerm(AB + 1), x, y1, z1), noiseGrad(noisePerm(BB + 1), x1, y1, z1));
    return noiseLerp(w, noiseLerp(v, l00, l10), noiseLerp(v, l01, l11));
}

float noisePerlin3(vec3 p, int seed) { return noisePerlin3(p, uint(seed)); }
