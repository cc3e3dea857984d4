#version 450
// voxc generated kernel "tunnel_subtract": field tunnel (fields.vox:31:7), mode subtract.
// Pipeline stage `subtract tunnel` (fields.vox:61:12).

// A field stage: every grid voxel's density d is combined with the field's value f there.
// One invocation owns a column of voxels along y, like the start kernel, so the nodes that do
// not depend on y are computed once per column; the rest are straight-line code per voxel,
// every float result `precise`, in the interpreter's operation order (voxc::FieldEvaluator).
// The runtime dispatches it per box of chunks (KernelPackage StagePlan::fieldBoxes); in a box
// where interval analysis proved the field one exact float (anchorCount.w == 1, the float's
// bits in anchorStart.w) only the combine runs, in a loop of its own so no DAG code is near it.
// Where the field's value is not finite the combine uses 0 instead (fieldDensity, counted);
// a constant box's value is finite (interval analysis proves no NaN or infinity exact).
// Noise calls the column shares work for (noise_column.glsl) fill noiseColumnValues a block of
// COLUMN_BLOCK voxels at a time, before the voxels of the block read them; point-set lookups along
// the column (point_set_column.glsl) fill pointSetColumnValues the same way.

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
// ---- begin nonfinite.glsl ----
// Non-finite densities (docs/language.md, "Non-finite values"), as voxc::NonFiniteCount does it
// on the CPU: a field stage stores 0 where its field is NaN or infinite, a grammar stores 0
// where a written value is not finite, and the stage counts them. The runtime copies this
// buffer out after every stage and resets it to {0, 0, 0xFFFFFFFF} (kBindingNonFinite).
layout(std430, set = 0, binding = 9) buffer NonFinite {
    uint countLow;   // replacements in the current stage, a 64-bit count in two halves
    uint countHigh;
    uint firstIndex; // the lowest grid index x + sx * (y + sy * z) replaced
} nonFinite;

// An exponent of all ones is an infinity or a NaN; tested on the bits, so no float
// optimisation of the driver can change the answer.
bool isFiniteFloat(float v) { return (floatBitsToUint(v) & 0x7F800000u) != 0x7F800000u; }

// `value` when finite; otherwise 0, counted at grid-local voxel `local`.
float finiteDensity(float value, ivec3 local) {
    if (isFiniteFloat(value)) return value;
    if (atomicAdd(nonFinite.countLow, 1u) == 0xFFFFFFFFu) atomicAdd(nonFinite.countHigh, 1u);
    atomicMin(nonFinite.firstIndex, uint(local.x + push.gridSize.x * (local.y + push.gridSize.y * local.z)));
    return 0.0;
}
// ---- end nonfinite.glsl ----
// ---- begin opaque_constants.glsl ----
// Field-expression constants kept from the shader compilers' own folding (docs/fuzzing.md).
// llvmpipe (lavapipe's NIR passes and its LLVM code builder) rewrites an operation with a
// constant zero operand as if signed zeros, infinities and NaN did not exist, `precise` or not:
// x + 0 -> x (so -0 stays -0), 0 - x -> -x (so +0 becomes -0), x * 0 -> +0 (also for a
// negative, infinite or NaN x), x / 0 -> NaN, 0 / x -> +0 (docs/fuzzing.md has the table).
// The interpreter computes these as IEEE does. Codegen passes the constants that could reach
// such an operation through opaqueConstant: the same value while the kernel runs (no dispatch
// has zero workgroups), but not one the compilers can fold. The test is the same for every
// invocation, so it costs a uniform select.
bool dispatchIsEmpty() { return gl_NumWorkGroups.x == 0u; }
float opaqueConstant(float c) { return dispatchIsEmpty() ? uintBitsToFloat(0x7FC00000u) : c; }
vec2 opaqueConstant(vec2 c) { return dispatchIsEmpty() ? vec2(uintBitsToFloat(0x7FC00000u)) : c; }
vec3 opaqueConstant(vec3 c) { return dispatchIsEmpty() ? vec3(uintBitsToFloat(0x7FC00000u)) : c; }

// A constant glslang leaves alone: it folds an expression of literals itself, in double from their
// decimal text, where the driver, which inlines this call, folds it in float as the interpreter
// computes it.
float driverFolded(float c) { return c; }
// ---- end opaque_constants.glsl ----

const int COLUMN_BLOCK = 256;

// The invocation's non-finite values, added to the stage's count once at the end of main
// (flushNonFiniteTally) rather than by finiteDensity's atomics at each voxel: the same count and
// lowest index. Why: llvmpipe runs an atomic as a loop over the lanes even when no lane takes the
// branch, so three such loops per voxel were a twentieth of a noise field's kernel.
uint nonFiniteTally = 0u;
uint nonFiniteTallyFirst = 0xFFFFFFFFu;

// `value` when finite; otherwise 0, tallied at grid-local voxel `local`.
float fieldDensity(float value, ivec3 local) {
    if (isFiniteFloat(value)) return value;
    nonFiniteTally += 1u;
    nonFiniteTallyFirst = min(nonFiniteTallyFirst, uint(local.x + push.gridSize.x * (local.y + push.gridSize.y * local.z)));
    return 0.0;
}

// The tally into the stage's 64-bit count (a carry out of countLow goes to countHigh) and lowest index.
void flushNonFiniteTally() {
    if (nonFiniteTally == 0u) return;
    if (atomicAdd(nonFinite.countLow, nonFiniteTally) > 0xFFFFFFFFu - nonFiniteTally) atomicAdd(nonFinite.countHigh, 1u);
    atomicMin(nonFinite.firstIndex, nonFiniteTallyFirst);
}
float noiseColumnValues[1][COLUMN_BLOCK];
// Each column noise call's argument: its y at the column's voxel y.
float noiseColumnArgY(int site, int y) {
    int localY = push.anchorStart.y + y * push.anchorStep.y;
    int worldY = push.gridOrigin.y + localY;
    switch (site) {
    case 0: { precise float r = (float(worldY) * 0.0799999982); return r; }
    }
    return 0.0;
}
// No point-set lookup shares work along the column.
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
// ---- begin noise_permutation.glsl ----
// Ken Perlin's permutation in private memory as pairs, for perlin3 and simplex3: entry i holds
// perm(i) in bits 0..7 and perm(i + 1) in bits 8..15, so one read serves both lookups their
// hashing makes at i and i + 1 (the values, so every result bit, are those of noisePerm;
// tests/codegen checks them against voxc::perlinPermutation). Why: llvmpipe reads a storage
// buffer lane by lane behind branches but a private array with one gather, and the permutation
// reads are most of a perlin3 or a simplex3. The table is a global with a constant initializer,
// i.e. stored from constants once per invocation at the top of main; filled from the noise-table
// buffer instead, each entry cost a lane-by-lane buffer read and a lane-by-lane store. It is not
// a `const` array: llvmpipe materialises a dynamically indexed constant array at every use.
int noisePermutationPairs[256] = int[256](
    41111, 35232, 23433, 23131, 3930, 33551, 3459, 51469, 24521, 24671, 13664, 49717, 59842, 2025, 57607, 36065,
    9356, 26404, 7783, 17694, 36421, 2190, 25352, 9571, 61477, 5616, 2581, 5898, 48663, 1726, 37894, 63380,
    30967, 60024, 19434, 75, 6656, 50458, 16069, 24126, 64606, 56316, 52187, 30155, 9077, 2851, 8203, 14624,
    45369, 8625, 22561, 60760, 38381, 14485, 22328, 44631, 5294, 32020, 34941, 43912, 43179, 17576, 44868, 19119,
    42314, 18341, 34375, 35718, 12427, 6960, 42523, 19878, 37453, 40594, 59294, 21479, 28499, 58735, 31461, 15482,
    54076, 34259, 59013, 56550, 27100, 23657, 10588, 14121, 11831, 62766, 10485, 62504, 26356, 36710, 13967, 16694,
    6465, 16153, 41279, 417, 55297, 20696, 18768, 53577, 19665, 33868, 48004, 53435, 22992, 4697, 43282, 51369,
    50376, 34756, 33415, 29826, 48244, 40892, 22175, 42070, 25764, 28004, 50797, 44486, 47789, 954, 16387, 13376,
    55604, 58073, 64226, 31994, 31612, 1403, 51717, 9930, 37670, 30355, 32374, 65406, 21247, 21842, 54357, 53204,
    52943, 15310, 58171, 12259, 4143, 14864, 4410, 46609, 48566, 7357, 10780, 57130, 47071, 43703, 54698, 30677,
    63607, 39160, 664, 11266, 39468, 41882, 18083, 56646, 39389, 26009, 39781, 42907, 11175, 44075, 2476, 33033,
    5761, 10006, 64807, 5117, 25107, 27746, 28268, 20334, 29007, 57457, 59616, 45800, 47538, 28857, 26736, 55912,
    63194, 25078, 58465, 64484, 8955, 61986, 49650, 61121, 53998, 37074, 3216, 48908, 46015, 41651, 61858, 20977,
    13137, 37171, 60305, 63979, 3833, 61198, 27631, 12651, 49201, 54976, 8150, 46367, 51125, 27335, 40298, 47261,
    21688, 52308, 45260, 29616, 31091, 12921, 11570, 32557, 1151, 38404, 65174, 35582, 60554, 52716, 24013, 56925,
    29406, 17266, 7491, 6173, 18456, 62280, 36339, 32909, 50048, 20163, 16974, 55106, 15831, 39997, 46236, 38836);

// (perm(i), perm(i + 1)).
ivec2 noisePermPair(int i) {
    int pair = noisePermutationPairs[i & 255];
    return ivec2(pair & 255, pair >> 8);
}
// ---- end noise_permutation.glsl ----
// ---- begin noise_perlin3.glsl ----
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
// ---- end noise_perlin3.glsl ----
// ---- begin math_functions.glsl ----
// Math builtins of field expressions whose GLSL built-in may be computed in another operation
// order (or with a fused multiply-add), or leaves NaN operands undefined (min, max, clamp):
// written out with `precise` exactly as the interpreter computes them
// (compiler/builtins/src/functions/Math.cpp). GLSL's own abs, floor, sqrt, sin and cos are used
// directly, and its pow where that is defined (mathPow).

// NaN tested on the bits (exponent all ones, mantissa not zero), beyond any float optimisation.
bool mathIsNan(float x) { return (floatBitsToUint(x) & 0x7FFFFFFFu) > 0x7F800000u; }

// IEEE minNum / maxNum (SPIR-V NMin / NMax): b < a ? b : a (a < b ? b : a), ties keeping a,
// except that a NaN a gives b; a NaN b loses the comparison. So a NaN operand is ignored.
float mathMin(float a, float b) { return mathIsNan(a) ? b : (b < a ? b : a); }
float mathMax(float a, float b) { return mathIsNan(a) ? b : (a < b ? b : a); }
vec2 mathMin(vec2 a, vec2 b) { return vec2(mathMin(a.x, b.x), mathMin(a.y, b.y)); }
vec3 mathMin(vec3 a, vec3 b) { return vec3(mathMin(a.x, b.x), mathMin(a.y, b.y), mathMin(a.z, b.z)); }
vec2 mathMax(vec2 a, vec2 b) { return vec2(mathMax(a.x, b.x), mathMax(a.y, b.y)); }
vec3 mathMax(vec3 a, vec3 b) { return vec3(mathMax(a.x, b.x), mathMax(a.y, b.y), mathMax(a.z, b.z)); }
vec2 mathMin(vec2 a, float b) { return mathMin(a, vec2(b)); }
vec3 mathMin(vec3 a, float b) { return mathMin(a, vec3(b)); }
vec2 mathMax(vec2 a, float b) { return mathMax(a, vec2(b)); }
vec3 mathMax(vec3 a, float b) { return mathMax(a, vec3(b)); }

// pow: NaN where GLSL leaves it undefined (x < 0; x = 0 with y <= 0) or exp2(y * log2(x)) is NaN
// while the C library's pow is not (a NaN operand; x = 1 with y infinite; x infinite with
// y = 0), as Math.cpp's powOf; GLSL's pow elsewhere.
bool mathIsInf(float x) { return (floatBitsToUint(x) & 0x7FFFFFFFu) == 0x7F800000u; }
float mathPow(float x, float y) {
    bool undefined = mathIsNan(x) || mathIsNan(y) || x < 0.0 || (x == 0.0 && y <= 0.0) ||
                     (x == 1.0 && mathIsInf(y)) || (mathIsInf(x) && y == 0.0);
    return undefined ? uintBitsToFloat(0x7FC00000u) : pow(x, y);
}
vec2 mathPow(vec2 x, vec2 y) { return vec2(mathPow(x.x, y.x), mathPow(x.y, y.y)); }
vec3 mathPow(vec3 x, vec3 y) { return vec3(mathPow(x.x, y.x), mathPow(x.y, y.y), mathPow(x.z, y.z)); }

// mix(x, y, a) = x * (1 - a) + y * a, GLSL's definition.
float mathMix(float x, float y, float a) { precise float r = x * (1.0 - a) + y * a; return r; }
vec2 mathMix(vec2 x, vec2 y, vec2 a) { precise vec2 r = x * (1.0 - a) + y * a; return r; }
vec3 mathMix(vec3 x, vec3 y, vec3 a) { precise vec3 r = x * (1.0 - a) + y * a; return r; }
vec2 mathMix(vec2 x, vec2 y, float a) { return mathMix(x, y, vec2(a)); }
vec3 mathMix(vec3 x, vec3 y, float a) { return mathMix(x, y, vec3(a)); }

// smoothstep: t = clamp((x - e0) / (e1 - e0), 0, 1); t * t * (3 - 2 t), GLSL's definition,
// also defined (as written) when e0 >= e1.
float mathSmoothstep(float e0, float e1, float x) {
    precise float t = mathMin(mathMax((x - e0) / (e1 - e0), 0.0), 1.0);
    precise float r = t * t * (3.0 - 2.0 * t);
    return r;
}
vec2 mathSmoothstep(vec2 e0, vec2 e1, vec2 x) {
    return vec2(mathSmoothstep(e0.x, e1.x, x.x), mathSmoothstep(e0.y, e1.y, x.y));
}
vec3 mathSmoothstep(vec3 e0, vec3 e1, vec3 x) {
    return vec3(mathSmoothstep(e0.x, e1.x, x.x), mathSmoothstep(e0.y, e1.y, x.y), mathSmoothstep(e0.z, e1.z, x.z));
}
vec2 mathSmoothstep(float e0, float e1, vec2 x) { return mathSmoothstep(vec2(e0), vec2(e1), x); }
vec3 mathSmoothstep(float e0, float e1, vec3 x) { return mathSmoothstep(vec3(e0), vec3(e1), x); }

// fract(x) = x - floor(x), GLSL's definition (1.0 for tiny negative x, as on the CPU).
float mathFract(float x) { precise float r = x - floor(x); return r; }
vec2 mathFract(vec2 x) { precise vec2 r = x - floor(x); return r; }
vec3 mathFract(vec3 x) { precise vec3 r = x - floor(x); return r; }

// dot and length summed left to right.
float mathDot(vec2 a, vec2 b) { precise float r = a.x * b.x + a.y * b.y; return r; }
float mathDot(vec3 a, vec3 b) { precise float r = a.x * b.x + a.y * b.y + a.z * b.z; return r; }
float mathLength(vec2 a) { return sqrt(mathDot(a, a)); }
float mathLength(vec3 a) { return sqrt(mathDot(a, a)); }
// ---- end math_functions.glsl ----
// ---- begin noise_column.glsl ----
// fbm, turbulence and perlin3 along a field kernel's column: the same bits as noiseOctaveSum
// (noise_fractal.glsl) and noisePerlin3 for every voxel, with the work shared where it can be.
// Why: on llvmpipe a perlin3 is mostly its seven permutation reads (a private-array gather each)
// and its eight gradient selections. The codegen (FieldKernel.cpp) takes this path for a call
// whose argument's x and z are the same along the column and whose y depends on y alone, so per
// octave the x/z lattice work is done once per column, the hashes and the gradients' x/z parts
// once per lattice cell along y (loops whose trip counts are the same in every lane, so llvmpipe
// really skips), and each voxel pays only its y fraction, eight adds and seven lerps.
// Requires noise_common.glsl, noise_permutation.glsl, noise_perlin3.glsl and, from the kernel,
// COLUMN_BLOCK, the array noiseColumnValues[sites][COLUMN_BLOCK] and noiseColumnArgY(site, y): the
// argument's y at voxel y.

// One octave's column constants: the scaled x and z, their lattice cells and fade weights.
struct NoiseColumnOctave {
    bool finiteXZ;
    float x, x1, z, z1, u, w;
    int X, Z;
    ivec2 hX;
    int offsetY;
};

NoiseColumnOctave noiseColumnOctave(float px, float pz, float frequency, uint seed) {
    NoiseColumnOctave o;
    precise float qx = px * frequency;
    precise float qz = pz * frequency;
    o.finiteXZ = isFiniteFloat(qx) && isFiniteFloat(qz);
    precise float fx = floor(qx);
    precise float fz = floor(qz);
    precise float x = qx - fx;
    precise float z = qz - fz;
    precise float x1 = x - 1.0;
    precise float z1 = z - 1.0;
    o.x = x;
    o.z = z;
    o.x1 = x1;
    o.z1 = z1;
    o.u = noiseFade(x);
    o.w = noiseFade(z);
    ivec3 offset = noiseSeedOffset(seed);
    o.X = (noiseLatticeIndex(fx) + offset.x) & 255;
    o.Z = (noiseLatticeIndex(fz) + offset.z) & 255;
    o.hX = noisePermPair(o.X);
    o.offsetY = offset.y;
    return o;
}

// noiseGrad(hash, x, y, z) with x and z fixed: (+-u) + (+-v) where at most one of u, v is y, so it
// is part + (+-y) (IEEE addition commutes) or, without y, the constant part itself.
struct NoiseColumnGradient {
    float part;
    uint ySign; // XORed into y's bits: the sign flip of -y
    bool usesY;
};

NoiseColumnGradient noiseColumnGradient(int hash, float x, float z) {
    int h = hash & 15;
    uint uSign = uint(h) << 31;                  // (h & 1) != 0: -u
    uint vSign = (uint(h) << 30) & 0x80000000u;  // (h & 2) != 0: -v
    NoiseColumnGradient g;
    if (h < 4) { // u = x, v = y
        g.part = uintBitsToFloat(floatBitsToUint(x) ^ uSign);
        g.ySign = vSign;
        g.usesY = true;
    } else if (h >= 8) { // u = y, v = x (h = 12, 14) or z
        g.part = uintBitsToFloat(floatBitsToUint((h & 13) == 12 ? x : z) ^ vSign);
        g.ySign = uSign;
        g.usesY = true;
    } else { // u = x, v = z
        precise float r = uintBitsToFloat(floatBitsToUint(x) ^ uSign) + uintBitsToFloat(floatBitsToUint(z) ^ vSign);
        g.part = r;
        g.ySign = 0u;
        g.usesY = false;
    }
    return g;
}

float noiseColumnGradientAt(NoiseColumnGradient g, float y) {
    precise float r = g.part + uintBitsToFloat(floatBitsToUint(y) ^ g.ySign);
    return g.usesY ? r : g.part;
}

// The eight corners' gradients of one lattice cell, in noisePerlin3's corner order.
struct NoiseColumnCell {
    NoiseColumnGradient g000, g100, g010, g110, g001, g101, g011, g111;
};

NoiseColumnCell noiseColumnCell(NoiseColumnOctave o, float fy) {
    int Y = (noiseLatticeIndex(fy) + o.offsetY) & 255;
    ivec2 hA = noisePermPair(o.hX.x + Y);
    ivec2 hB = noisePermPair(o.hX.y + Y);
    ivec2 hAA = noisePermPair(hA.x + o.Z);
    ivec2 hAB = noisePermPair(hA.y + o.Z);
    ivec2 hBA = noisePermPair(hB.x + o.Z);
    ivec2 hBB = noisePermPair(hB.y + o.Z);
    NoiseColumnCell c;
    c.g000 = noiseColumnGradient(hAA.x, o.x, o.z);
    c.g100 = noiseColumnGradient(hBA.x, o.x1, o.z);
    c.g010 = noiseColumnGradient(hAB.x, o.x, o.z);
    c.g110 = noiseColumnGradient(hBB.x, o.x1, o.z);
    c.g001 = noiseColumnGradient(hAA.y, o.x, o.z1);
    c.g101 = noiseColumnGradient(hBA.y, o.x1, o.z1);
    c.g011 = noiseColumnGradient(hAB.y, o.x, o.z1);
    c.g111 = noiseColumnGradient(hBB.y, o.x1, o.z1);
    return c;
}

// noisePerlin3 at (x, qy, z) of the octave, qy in the cell whose floor is fy.
float noiseColumnPerlin(NoiseColumnOctave o, NoiseColumnCell c, float qy, float fy) {
    if (!(o.finiteXZ && isFiniteFloat(qy))) return noiseNaN();
    precise float y = qy - fy;
    precise float y1 = y - 1.0;
    float v = noiseFade(y);
    float l00 = noiseLerp(o.u, noiseColumnGradientAt(c.g000, y), noiseColumnGradientAt(c.g100, y));
    float l10 = noiseLerp(o.u, noiseColumnGradientAt(c.g010, y1), noiseColumnGradientAt(c.g110, y1));
    float l01 = noiseLerp(o.u, noiseColumnGradientAt(c.g001, y), noiseColumnGradientAt(c.g101, y));
    float l11 = noiseLerp(o.u, noiseColumnGradientAt(c.g011, y1), noiseColumnGradientAt(c.g111, y1));
    return noiseLerp(o.w, noiseLerp(v, l00, l10), noiseLerp(v, l01, l11));
}

// noiseColumnValues[site][y - firstY] = noiseOctaveSum(p, ...) of kind 0 (fbm) or 1 (turbulence)
// for firstY <= y < lastY, p = (px, noiseColumnArgY(site, y), pz). Octave by octave, each voxel's
// sum takes its terms in noiseOctaveSum's order, so the same bits.
void noiseColumnFill(int site, int firstY, int lastY, float px, float pz, int octaves, float lacunarity, float gain,
                     uint seed, int kind) {
    precise float amplitude = 1.0;
    precise float frequency = 1.0;
    int count = min(max(octaves, 1), 16);
    for (int k = 0; k < count; ++k) {
        NoiseColumnOctave o = noiseColumnOctave(px, pz, frequency, noiseSubstream(seed, uint(k)));
        int y = firstY;
        precise float qy = noiseColumnArgY(site, y) * frequency;
        while (y < lastY) {
            precise float fy = floor(qy);
            NoiseColumnCell cell = noiseColumnCell(o, fy);
            bool inCell = true;
            while (inCell) {
                float n = noiseColumnPerlin(o, cell, qy, fy);
                precise float weighted = amplitude * (kind == 0 ? n : abs(n));
                float before = noiseColumnValues[site][y - firstY];
                precise float sum = before + weighted;
                noiseColumnValues[site][y - firstY] = k == 0 ? weighted : sum;
                ++y;
                qy = noiseColumnArgY(site, y) * frequency;
                // Not `floor(qy) == fy` for a non-finite qy: NaN never equals, so each such voxel is a cell.
                inCell = y < lastY && floor(qy) == fy;
            }
        }
        amplitude = amplitude * gain;
        frequency = frequency * lacunarity;
    }
}
// ---- end noise_column.glsl ----

layout(local_size_x = 8, local_size_y = 1, local_size_z = 8) in;
// Each invocation handles this many consecutive anchors of its dispatch per axis
// (voxc::Kernel::anchorsPerInvocation; the runtime sizes the dispatch by it).
const ivec3 ANCHORS_PER_INVOCATION = ivec3(1, 64, 1);

void main() {
    ivec3 first = ivec3(gl_GlobalInvocationID) * ANCHORS_PER_INVOCATION;
    if (any(greaterThanEqual(first, push.anchorCount.xyz))) return;
    ivec3 last = min(first + ANCHORS_PER_INVOCATION, push.anchorCount.xyz);

    if (push.anchorCount.w == 1) {
        float constantValue = intBitsToFloat(push.anchorStart.w);
        for (int z = first.z; z < last.z; ++z) {
            for (int x = first.x; x < last.x; ++x) {
                for (int y = first.y; y < last.y;) {
                    ivec3 runStart = push.anchorStart.xyz + ivec3(x, y, z) * push.anchorStep.xyz;
                    int runEnd = columnRunEnd(runStart, y, last.y);
                    for (int address = voxelAddress(runStart); y < runEnd; ++y, address += push.gridOrigin.w) {
                        ivec3 local = push.anchorStart.xyz + ivec3(x, y, z) * push.anchorStep.xyz;
                        // subtract: d = min(d, 1 - f)
                        float density = voxels.density[address];
                        precise float carved = 1.0 - constantValue;
                        voxels.density[address] = carved < density ? carved : density;
                    }
                }
            }
        }
        return;
    }

    for (int z = first.z; z < last.z; ++z) {
        for (int x = first.x; x < last.x; ++x) {
            ivec3 columnLocal = push.anchorStart.xyz + ivec3(x, first.y, z) * push.anchorStep.xyz;
            // Integer sum first, then one conversion, as the interpreter does.
            ivec3 columnWorld = push.gridOrigin.xyz + columnLocal;
            precise float n0 = float(columnWorld.x); // wx (fields.vox:32:28)
            precise float n2 = float(columnWorld.z); // wz (fields.vox:32:28)
            precise float noiseColumnX0 = (n0 * 0.0799999982);
            precise float noiseColumnZ0 = (n2 * 0.0799999982);
            precise float n10 = float(columnWorld.x); // x (fields.vox:33:17)
            precise float n12 = float(columnWorld.z); // z (fields.vox:33:17)
            for (int blockY = first.y; blockY < last.y; blockY += COLUMN_BLOCK) {
                int blockEnd = min(blockY + COLUMN_BLOCK, last.y);
                noiseColumnFill(0, blockY, blockEnd, noiseColumnX0, noiseColumnZ0, 1, 1.0, 1.0, uint(12), 0);
                for (int y = blockY; y < blockEnd;) {
                    ivec3 runStart = push.anchorStart.xyz + ivec3(x, y, z) * push.anchorStep.xyz;
                    int runEnd = columnRunEnd(runStart, y, blockEnd);
                    for (int address = voxelAddress(runStart); y < runEnd; ++y, address += push.gridOrigin.w) {
                        ivec3 local = push.anchorStart.xyz + ivec3(x, y, z) * push.anchorStep.xyz;
                        ivec3 world = push.gridOrigin.xyz + local;
                        precise float n1 = float(world.y); // wy (fields.vox:32:28)
                        precise vec3 n3 = vec3(n0, n1, n2); // vec3 (fields.vox:32:28)
                        precise vec3 n5 = (n3 * 0.0799999982); // mul (fields.vox:32:28)
                        precise float n7 = noiseColumnValues[0][y - blockY]; // perlin3 along the column (fields.vox:32:20)
                        precise float n9 = (3.0 * n7); // mul (fields.vox:32:16)
                        precise float n11 = float(world.y); // y (fields.vox:33:17)
                        precise vec3 n13 = vec3(n10, n11, n12); // vec3 (fields.vox:33:17)
                        precise vec3 n17 = (n13 - opaqueConstant(vec3(0.0, 16.0, 20.0))); // sub (fields.vox:24:21)
                        precise float n18 = mathDot(n17, opaqueConstant(vec3(64.0, 6.0, 24.0))); // dot (fields.vox:24:17)
                        precise float n20 = (n18 / 4708.0); // div (fields.vox:24:17)
                        precise float n22 = mathMin(mathMax(n20, opaqueConstant(0.0)), opaqueConstant(1.0)); // clamp (fields.vox:24:11)
                        precise vec3 n23 = (opaqueConstant(vec3(64.0, 6.0, 24.0)) * n22); // mul (fields.vox:25:19)
                        precise vec3 n24 = (opaqueConstant(vec3(0.0, 16.0, 20.0)) + n23); // add (fields.vox:25:15)
                        precise vec3 n25 = (n13 - n24); // sub (fields.vox:25:10)
                        precise float n26 = mathLength(n25); // length (fields.vox:25:3)
                        precise float n27 = (n26 + n9); // add (fields.vox:33:9)
                        precise float n29 = (5.0 - n27); // sub (fields.vox:19:54)
                        precise float n30 = mathMin(mathMax(n29, opaqueConstant(0.0)), opaqueConstant(1.0)); // clamp (fields.vox:19:48)
                        float fieldValue = fieldDensity(n30, local);
                        // subtract: d = min(d, 1 - f)
                        float density = voxels.density[address];
                        precise float carved = 1.0 - fieldValue;
                        voxels.density[address] = carved < density ? carved : density;
                    }
                }
            }
        }
    }
    flushNonFiniteTally();
}
