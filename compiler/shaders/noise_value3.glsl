// Value noise: mirrors voxc::noise::value3 (compiler/builtins/src/functions/HashNoise.cpp).
// Requires noise_common.glsl.

float noiseLatticeValue(ivec3 c, uint seed) {
    precise float r = float(noiseCellHash(c, seed) >> 8) * 1.1920928955078125e-7 - 1.0;
    return r;
}

float noiseValue3(vec3 p, int seedBits) {
    if (!noiseFinite(p)) return noiseNaN();
    uint seed = uint(seedBits);
    precise vec3 f = floor(p);
    ivec3 c = noiseHashCoordinate(f);
    precise vec3 local = p - f;
    float u = noiseFade(local.x);
    float v = noiseFade(local.y);
    float w = noiseFade(local.z);
    float l00 = noiseLerp(u, noiseLatticeValue(c, seed), noiseLatticeValue(c + ivec3(1, 0, 0), seed));
    float l10 = noiseLerp(u, noiseLatticeValue(c + ivec3(0, 1, 0), seed), noiseLatticeValue(c + ivec3(1, 1, 0), seed));
    float l01 = noiseLerp(u, noiseLatticeValue(c + ivec3(0, 0, 1), seed), noiseLatticeValue(c + ivec3(1, 0, 1), seed));
    float l11 = noiseLerp(u, noiseLatticeValue(c + ivec3(0, 1, 1), seed), noiseLatticeValue(c + ivec3(1, 1, 1), seed));
    return noiseLerp(w, noiseLerp(v, l00, l10), noiseLerp(v, l01, l11));
}
