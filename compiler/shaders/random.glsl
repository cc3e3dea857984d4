// Counter-based randomness: mirrors compiler/program/src/Random.cpp bit for bit.

// Chris Wellons' "lowbias32" integer finaliser.
uint mix32(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

const uint STREAM_RULE_CHOICE = 0u;
const uint STREAM_PROBABILITY = 1u;

uint anchorHash(uint seed, uint iteration, uint sweep, ivec3 anchorWorld, uint stream) {
    uint h = mix32(stream);
    h = mix32(uint(anchorWorld.z) ^ h);
    h = mix32(uint(anchorWorld.y) ^ h);
    h = mix32(uint(anchorWorld.x) ^ h);
    h = mix32(sweep ^ h);
    h = mix32(iteration ^ h);
    return mix32(seed ^ h);
}
