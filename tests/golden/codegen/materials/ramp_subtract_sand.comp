#version 450
#define VOXC_MATERIALS
// voxc generated kernel "ramp_subtract_sand": field ramp (materials.vox:21:1), mode subtract.
// Pipeline stage `subtract ramp material 2` (materials.vox:90:40).

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
// No noise call shares work along the column.
// No point-set lookup shares work along the column.
// No function library needed.

layout(local_size_x = 8, local_size_y = 1, local_size_z = 8) in;
// Each invocation handles this many consecutive anchors of its dispatch per axis
// (voxc::Kernel::anchorsPerInvocation; the runtime sizes the dispatch by it).
const ivec3 ANCHORS_PER_INVOCATION = ivec3(1, 36, 1);

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
                        // subtract: d = min(d, 1 - f); material 2 where 1 - f wins and is solid
                        float density = voxels.density[address];
                        precise float carved = 1.0 - constantValue;
                        bool wins = carved < density;
                        float result = wins ? carved : density;
                        voxels.density[address] = result;
                        if (wins && result >= 0.5) materials.material[address] = 2u;
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
            precise float n0 = float(columnWorld.x - (-3)); // x (materials.vox:21:1)
            precise float n2 = (n0 * 0.0399999991); // mul (materials.vox:21:1)
            for (int blockY = first.y; blockY < last.y; blockY += COLUMN_BLOCK) {
                int blockEnd = min(blockY + COLUMN_BLOCK, last.y);
                // Nothing to fill per block.
                for (int y = blockY; y < blockEnd;) {
                    ivec3 runStart = push.anchorStart.xyz + ivec3(x, y, z) * push.anchorStep.xyz;
                    int runEnd = columnRunEnd(runStart, y, blockEnd);
                    for (int address = voxelAddress(runStart); y < runEnd; ++y, address += push.gridOrigin.w) {
                        ivec3 local = push.anchorStart.xyz + ivec3(x, y, z) * push.anchorStep.xyz;
                        ivec3 world = push.gridOrigin.xyz + local;
                        // Every value is the same along the column.
                        float fieldValue = fieldDensity(n2, local);
                        // subtract: d = min(d, 1 - f); material 2 where 1 - f wins and is solid
                        float density = voxels.density[address];
                        precise float carved = 1.0 - fieldValue;
                        bool wins = carved < density;
                        float result = wins ? carved : density;
                        voxels.density[address] = result;
                        if (wins && result >= 0.5) materials.material[address] = 2u;
                    }
                }
            }
        }
    }
    flushNonFiniteTally();
}
