// Ken Perlin's improved noise (2002) with a seed-derived lattice translation: mirrors
// voxc::noise::perlin3 (compiler/builtins/src/functions/GradientNoise.cpp).
// Requires noise_common.glsl and noise_permutation.glsl.

float noisePerlin3(vec3 p, uint seed) {
    if (!noiseFinite(p)) return noiseNaN();
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
    ivec2 hX = noisePermPair(X);
    int A = hX.x + Y;
    int B = hX.y + Y;
    ivec2 hA = noisePermPair(A);
    ivec2 hB = noisePermPair(B);
    int AA = hA.x + Z;
    int AB = hA.y + Z;
    int BA = hB.x + Z;
    int BB = hB.y + Z;
    // Corner hashes: .x at z, .y at z + 1.
    ivec2 hAA = noisePermPair(AA);
    ivec2 hAB = noisePermPair(AB);
    ivec2 hBA = noisePermPair(BA);
    ivec2 hBB = noisePermPair(BB);
    precise float x1 = x - 1.0;
    precise float y1 = y - 1.0;
    precise float z1 = z - 1.0;
    float l00 = noiseLerp(u, noiseGrad(hAA.x, x, y, z), noiseGrad(hBA.x, x1, y, z));
    float l10 = noiseLerp(u, noiseGrad(hAB.x, x, y1, z), noiseGrad(hBB.x, x1, y1, z));
    float l01 = noiseLerp(u, noiseGrad(hAA.y, x, y, z1), noiseGrad(hBA.y, x1, y, z1));
    float l11 = noiseLerp(u, noiseGrad(hAB.y, x, y1, z1), noiseGrad(hBB.y, x1, y1, z1));
    return noiseLerp(w, noiseLerp(v, l00, l10), noiseLerp(v, l01, l11));
}

float noisePerlin3(vec3 p, int seed) { return noisePerlin3(p, uint(seed)); }
