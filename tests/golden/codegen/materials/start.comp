#version 450
#define VOXC_MATERIALS
// voxc generated kernel "start": the start state of materials.vox.
// Shapes in order; each overwrites the density where it is solid:
//   fill value 0.0 (materials.vox:6:3)
//   box value 1.0 material 1 (materials.vox:7:3)
//   sphere value 1.0 material 2 (materials.vox:8:3)
//   box value 1.0 material 3 (materials.vox:9:3)

// The start state: every grid voxel gets the start block's shapes in order over air
// (density 0, material none), as voxc::startVoxel does on the CPU. One invocation owns a
// column of voxels along y, so per-column values (a heightfield's height) are computed once,
// and the chunk table is consulted once per chunk the column enters instead of once per voxel.

// ---- begin common.glsl ----
// Declarations every voxc kernel shares: the push block (voxc::PushBlock in
// compiler/codegen/include/voxc/codegen/KernelPackage.h, field for field) and the first three
// storage buffers of descriptor set 0 (kBindingVoxels, kBindingChunkTable, kBindingNoiseTables;
// the chunk-skipping buffers are in chunks.glsl).

layout(push_constant, std430) uniform PushBlock {
    ivec4 gridOrigin;  // xyz: world coordinate of grid voxel (0,0,0); w: chunk size
    ivec4 gridSize;    // xyz: grid size in voxels; w: seed (bit pattern)
    ivec4 chunkBase;   // xyz: world chunk coordinate of chunk-table entry 0; w: iteration
    ivec4 chunkCount;  // xyz: chunk-table extents; w: sweep index within its grammar
    ivec4 anchorStart; // xyz: grid-local first anchor of this dispatch; w: active-dispatch record
    ivec4 anchorStep;  // xyz: distance between the anchors of one dispatch; w: log2 tile size
    ivec4 anchorCount; // xyz: anchors per axis in this dispatch; w: 1 = indirect over active tiles
} push;

// Densities, chunk-major: all voxels of one chunk slot, then the next slot.
layout(std430, set = 0, binding = 0) buffer Voxels {
    float density[];
} voxels;

#ifdef VOXC_MATERIALS
// Material ids (voxc::Material, 0 = none), one uint per voxel at the densities' addresses
// (kBindingMaterials); declared only by kernels of programs that use materials.
layout(std430, set = 0, binding = 8) buffer Materials {
    uint material[];
} materials;
#endif

// Chunk-table entry -> chunk slot; entries run x fastest over push.chunkCount.xyz.
layout(std430, set = 0, binding = 1) readonly buffer ChunkTable {
    int chunkSlot[];
} chunkTable;

// Ken Perlin's 256-entry permutation (voxc::perlinPermutation), read by noise_common.glsl. It is a
// buffer, not a constant array, because some drivers (llvmpipe) materialise a dynamically indexed
// constant array on every call, which cost ~1000x.
layout(std430, set = 0, binding = 2) readonly buffer NoiseTables {
    int perlinPermutation[];
} noiseTables;

// Buffer index of a grid-local voxel, exactly as voxc::ChunkLayout::address computes it.
// Chunks are aligned to world coordinates and their size is a power of two, so the
// arithmetic shift and the mask are floor division and remainder, negatives included.
int voxelAddress(ivec3 local) {
    int chunkSize = push.gridOrigin.w;
    int chunkShift = findMSB(chunkSize);
    ivec3 world = push.gridOrigin.xyz + local;
    ivec3 chunk = world >> chunkShift;
    ivec3 inside = world & (chunkSize - 1);
    ivec3 entry = chunk - push.chunkBase.xyz;
    int slot = chunkTable.chunkSlot[entry.x + push.chunkCount.x * (entry.y + push.chunkCount.y * entry.z)];
    return slot * chunkSize * chunkSize * chunkSize + inside.x + chunkSize * (inside.y + chunkSize * inside.z);
}

// A column walk along y (anchor step 1) goes in runs that stay inside one chunk: the run starting
// at grid-local voxel `local` (walk index y) ends before index columnRunEnd, at `last` at the latest;
// its first address comes from the chunk table and each next one is chunkSize further. Every lane
// of a dispatch walks the same y, so the runs end together: llvmpipe leaves a loop once all lanes
// have, but runs both sides of a branch, so a lookup under `if` would cost every voxel.
int columnRunEnd(ivec3 local, int y, int last) {
    int chunkSize = push.gridOrigin.w;
    int worldY = push.gridOrigin.y + local.y;
    return min(last, y + chunkSize - (worldY & (chunkSize - 1)));
}
// ---- end common.glsl ----
// ---- begin random.glsl ----
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
// ---- end random.glsl ----
// ---- begin perlin.glsl ----
// 2D improved Perlin noise and the start state's heightfield: mirrors
// compiler/builtins/src/Perlin.cpp. Every float result is `precise` so the compiler may not fuse
// multiply-adds, which keeps the GPU bit-identical to the interpreter.
// Requires common.glsl and random.glsl; shares the lattice helpers of noise_common.glsl
// (the permutation comes from the noise-table buffer, one table for both sides).

// ---- begin noise_common.glsl ----
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
// ---- end noise_common.glsl ----

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
// ---- end perlin.glsl ----

layout(local_size_x = 8, local_size_y = 1, local_size_z = 8) in;
// Each invocation handles this many consecutive anchors of its dispatch per axis
// (voxc::Kernel::anchorsPerInvocation; the runtime sizes the dispatch by it).
const ivec3 ANCHORS_PER_INVOCATION = ivec3(1, 36, 1);

void main() {
    ivec3 first = ivec3(gl_GlobalInvocationID) * ANCHORS_PER_INVOCATION;
    if (any(greaterThanEqual(first, push.anchorCount.xyz))) return;
    ivec3 last = min(first + ANCHORS_PER_INVOCATION, push.anchorCount.xyz);
    uint seed = uint(push.gridSize.w);

    for (int z = first.z; z < last.z; ++z) {
        for (int x = first.x; x < last.x; ++x) {
            ivec3 columnLocal = push.anchorStart.xyz + ivec3(x, first.y, z) * push.anchorStep.xyz;
            ivec3 world = push.gridOrigin.xyz + columnLocal;
            // No shape has a per-column value.
            for (int y = first.y; y < last.y;) {
                ivec3 runStart = push.anchorStart.xyz + ivec3(x, y, z) * push.anchorStep.xyz;
                int runEnd = columnRunEnd(runStart, y, last.y);
                for (int address = voxelAddress(runStart); y < runEnd; ++y, address += push.gridOrigin.w) {
                    ivec3 local = push.anchorStart.xyz + ivec3(x, y, z) * push.anchorStep.xyz;
                    world = push.gridOrigin.xyz + local;
                    float density = 0.0;
                    uint material = 0u;
                    // fill (materials.vox:6:3)
                    {
                        ivec3 local = world - ivec3(-3, 2, -9);
                        bool inside = false;
                        inside = true;
                        if (inside) {
                            density = 0.0;
                        }
                    }
                    // box (materials.vox:7:3)
                    {
                        ivec3 local = world - ivec3(-3, 2, -9);
                        bool inside = false;
                        inside = all(greaterThanEqual(vec3(local), vec3(0.0, 0.0, 0.0))) && all(lessThan(vec3(local), vec3(40.0, 14.0, 28.0)));
                        if (inside) {
                            density = 1.0;
                            material = 1u;
                        }
                    }
                    // sphere (materials.vox:8:3)
                    {
                        ivec3 local = world - ivec3(-3, 2, -9);
                        bool inside = false;
                        precise vec3 d = vec3(local) - vec3(20.0, 16.0, 14.0);
                        precise float distanceSquared = d.x * d.x + d.y * d.y + d.z * d.z;
                        inside = distanceSquared <= 49.0;
                        if (inside) {
                            density = 1.0;
                            material = 2u;
                        }
                    }
                    // box (materials.vox:9:3)
                    {
                        ivec3 local = world - ivec3(-3, 2, -9);
                        bool inside = false;
                        inside = all(greaterThanEqual(vec3(local), vec3(0.0, 4.0, 0.0))) && all(lessThan(vec3(local), vec3(1.0, 10.0, 28.0)));
                        if (inside) {
                            density = 1.0;
                            material = 3u;
                        }
                    }
                    materials.material[address] = material;
                    voxels.density[address] = density;
                }
            }
        }
    }
}
