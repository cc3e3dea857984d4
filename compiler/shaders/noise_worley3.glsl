// Worley (cellular) noise, F1 and F2: mirrors voxc::noise::worley3
// (compiler/builtins/src/functions/HashNoise.cpp). Requires noise_common.glsl.

vec2 noiseWorley3(vec3 p, int seedBits) {
    if (!noiseFinite(p)) return vec2(noiseNaN());
    uint seed = uint(seedBits);
    precise vec3 f = floor(p);
    ivec3 c = noiseHashCoordinate(f);
    precise vec3 local = p - f;
    float f1 = 100.0;
    float f2 = 100.0;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                uint hx = noiseCellHash(c + ivec3(dx, dy, dz), seed);
                uint hy = mix32(hx);
                uint hz = mix32(hy);
                precise float ox = float(dx) + noiseUnitFloat(hx) - local.x;
                precise float oy = float(dy) + noiseUnitFloat(hy) - local.y;
                precise float oz = float(dz) + noiseUnitFloat(hz) - local.z;
                precise float d = ox * ox + oy * oy + oz * oz;
                if (d < f1) {
                    f2 = f1;
                    f1 = d;
                } else if (d < f2) {
                    f2 = d;
                }
            }
    return vec2(sqrt(f1), sqrt(f2));
}

float noiseWorleyF1(vec3 p, int seed) { return noiseWorley3(p, seed).x; }
float noiseWorleyF2(vec3 p, int seed) { return noiseWorley3(p, seed).y; }
float noiseWorleyF2F1(vec3 p, int seed) {
    vec2 f = noiseWorley3(p, seed);
    precise float r = f.y - f.x;
    return r;
}
