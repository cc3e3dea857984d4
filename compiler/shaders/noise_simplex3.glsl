// 3D simplex noise: mirrors voxc::noise::simplex3 (compiler/builtins/src/functions/GradientNoise.cpp).
// Requires noise_common.glsl and noise_permutation.glsl.

float noiseSimplexCorner(int hash, float x, float y, float z) {
    precise float t = 0.5 - x * x - y * y - z * z;
    if (t <= 0.0) return 0.0;
    precise float t2 = t * t;
    precise float r = t2 * t2 * noiseGrad(hash, x, y, z);
    return r;
}

float noiseSimplex3(vec3 p, int seedBits) {
    uint seed = uint(seedBits);
    const float skew = 0.333333343;
    const float unskew = 0.166666672;
    precise float s = (p.x + p.y + p.z) * skew;
    precise float fi = floor(p.x + s);
    precise float fj = floor(p.y + s);
    precise float fk = floor(p.z + s);
    if (!noiseFinite(vec3(fi, fj, fk))) return noiseNaN(); // p not finite, or the skew overflowed
    precise float t = (fi + fj + fk) * unskew;
    precise float x0 = p.x - (fi - t);
    precise float y0 = p.y - (fj - t);
    precise float z0 = p.z - (fk - t);
    ivec3 c1, c2;
    if (x0 >= y0) {
        if (y0 >= z0) { c1 = ivec3(1, 0, 0); c2 = ivec3(1, 1, 0); }
        else if (x0 >= z0) { c1 = ivec3(1, 0, 0); c2 = ivec3(1, 0, 1); }
        else { c1 = ivec3(0, 0, 1); c2 = ivec3(1, 0, 1); }
    } else {
        if (y0 < z0) { c1 = ivec3(0, 0, 1); c2 = ivec3(0, 1, 1); }
        else if (x0 < z0) { c1 = ivec3(0, 1, 0); c2 = ivec3(0, 1, 1); }
        else { c1 = ivec3(0, 1, 0); c2 = ivec3(1, 1, 0); }
    }
    precise float x1 = x0 - float(c1.x) + unskew;
    precise float y1 = y0 - float(c1.y) + unskew;
    precise float z1 = z0 - float(c1.z) + unskew;
    precise float x2 = x0 - float(c2.x) + 0.333333343;
    precise float y2 = y0 - float(c2.y) + 0.333333343;
    precise float z2 = z0 - float(c2.z) + 0.333333343;
    precise float x3 = x0 - 0.5;
    precise float y3 = y0 - 0.5;
    precise float z3 = z0 - 0.5;
    ivec3 offset = noiseSeedOffset(seed);
    int I = noiseLatticeIndex(fi) + offset.x;
    int J = noiseLatticeIndex(fj) + offset.y;
    int K = noiseLatticeIndex(fk) + offset.z;
    // Corner c hashes perm(I + c.x + perm(J + c.y + perm(K + c.z))), read as pairs: one at K, one
    // at J + perm(K + z) per z, one at I + perm(J + c.y + perm(K + c.z)) per corner.
    ivec2 hK = noisePermPair(K);
    ivec2 hJ0 = noisePermPair(J + hK.x);
    ivec2 hJ1 = noisePermPair(J + hK.y);
    int j1 = c1.z == 0 ? (c1.y == 0 ? hJ0.x : hJ0.y) : (c1.y == 0 ? hJ1.x : hJ1.y);
    int j2 = c2.z == 0 ? (c2.y == 0 ? hJ0.x : hJ0.y) : (c2.y == 0 ? hJ1.x : hJ1.y);
    ivec2 h1 = noisePermPair(I + j1);
    ivec2 h2 = noisePermPair(I + j2);
    float n0 = noiseSimplexCorner(noisePermPair(I + hJ0.x).x, x0, y0, z0);
    float n1 = noiseSimplexCorner(c1.x == 0 ? h1.x : h1.y, x1, y1, z1);
    float n2 = noiseSimplexCorner(c2.x == 0 ? h2.x : h2.y, x2, y2, z2);
    float n3 = noiseSimplexCorner(noisePermPair(I + hJ1.y).y, x3, y3, z3);
    precise float r = 76.0 * (n0 + n1 + n2 + n3);
    return r;
}
