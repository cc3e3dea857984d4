#version 450
// voxc generated kernel "smooth_sweep1" from sample.vox:40:1 grammar smooth.
// Sweep 1 runs every rule of window [1, 1, 1]: [10, 9, 5] anchors in [1, 1, 1] phases.
// Grammar stride [2, 1, 2], bounds [1, 2, 0]..[20, 11, 10], 1 iteration(s).
// Rules (declaration order):
//   impossible (sample.vox:48:3): removed, cell (0, 0, 0) passes no density so it never matches

// Every rule of this sweep can never match, so the sweep leaves the grid as it is. The
// kernel still exists so that each sweep of the dispatch plan has one.

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

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
// Each invocation handles this many consecutive anchors of its dispatch per axis
// (voxc::Kernel::anchorsPerInvocation; the runtime sizes the dispatch by it).
const ivec3 ANCHORS_PER_INVOCATION = ivec3(1, 1, 1);

void main() {
}
