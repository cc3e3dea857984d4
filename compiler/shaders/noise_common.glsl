// Lattice helpers of the noise builtins: mirrors compiler/builtins/src/functions/NoiseCommon.h.
// Every float result is `precise` (no fused multiply-add), so the GPU performs the
// interpreter's IEEE operations in the interpreter's order.
// Requires common.glsl (noiseTables) and random.glsl (mix32).

int noisePerm(int i) { return noiseTables.perlinPermutation[i & 255]; }

// Noise of a point with a NaN or infinite coordinate is NaN, as on the CPU (NoiseCommon.h's
// `finite`); tested on the bits, beyond any float optimisation.
bool noiseFinite(vec3 p) { return all(notEqual(floatBitsToUint(p) & 0x7F800000u, uvec3(0x7F800000u))); }
float noiseNaN() { return uintBitsToFloat(0x7FC00000u); }

float noiseFade(float t) {
    precise float r = t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
    return r;
}

float noiseLerp(float t, float a, float b) {
    precise float r = a + t * (b - a);
    return r;
}

// Perlin's reference gradient: 12 cube-edge directions, four of them repeated (hash & 15).
float noiseGrad(int hash, float x, float y, float z) {
    int h = hash & 15;
    float u = h < 8 ? x : y;
    float v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
    precise float r = ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
    return r;
}

// An integer-valued float reduced modulo 256, exact for every finite value.
int noiseLatticeIndex(float floored) {
    precise float r = floored - 256.0 * floor(floored * 0.00390625);
    return int(r);
}

// Seed-derived lattice translation, 8 bits per axis; seed 0 is untranslated.
ivec3 noiseSeedOffset(uint seed) {
    uint h = mix32(seed);
    return ivec3(int(h & 255u), int((h >> 8) & 255u), int((h >> 16) & 255u));
}

uint noiseSubstream(uint seed, uint stream) { return seed + stream * 0x9E3779B9u; }

// A float lattice coordinate as an int for hashing, saturated at +-2^30.
ivec3 noiseHashCoordinate(vec3 floored) {
    return ivec3(min(max(floored, vec3(-1073741824.0)), vec3(1073741824.0)));
}

uint noiseCellHash(ivec3 c, uint seed) {
    return mix32(uint(c.x) ^ mix32(uint(c.y) ^ mix32(uint(c.z) ^ mix32(seed))));
}

// 24 hash bits as a float in [0, 1).
float noiseUnitFloat(uint h) {
    precise float r = float(h >> 8) * 5.9604644775390625e-8;
    return r;
}
