// Speleothems: mirrors voxc::caves (compiler/generators/src/caves/Speleothems.cpp) operation for
// operation, every float result `precise`, so both sides write the same bits on lavapipe.
// Requires common.glsl, random.glsl, noise_common.glsl, noise_permutation.glsl, noise_simplex3.glsl,
// speleothem_air.glsl, and before this file the stage's constants (speleothem_grow.glsl's
// PARAMETERS section):
// SPELEOTHEM_KIND (0 stalactite, 1 stalagmite, 2 column, 3 hoodoo), SPELEOTHEM_CLUSTER_FREQUENCY,
// _CLUSTER_LOW, _CLUSTER_HIGH, _SPAWN_FREQUENCY, _SPAWN_THRESHOLD, _REACH_SCALE (voxc::
// speleothemReachScale), _GROWTH, _TAPER, _MIN_GAP,
// _MAX_GAP, SPELEOTHEM_MATERIAL (0: none written) and `bool speleothemProtected(ivec3 world)`.

// L (voxc::caves::speleothemLength): 0 when the run's midpoint fails the cluster range or the
// spawn threshold, else ceil(phi * gap / 2).
int speleothemLength(int worldX, int worldZ, int worldFloorY, int worldCeilingY) {
    precise float midY = float(worldFloorY + worldCeilingY) * 0.5;
    precise vec3 midpoint = vec3(float(worldX), midY, float(worldZ));
    uint seed = uint(push.gridSize.w); // the run's seed
    precise vec3 clusterPoint = midpoint * SPELEOTHEM_CLUSTER_FREQUENCY;
    float cluster = noiseSimplex3(clusterPoint, int(noiseSubstream(seed, 401u)));
    if (!(cluster >= SPELEOTHEM_CLUSTER_LOW && cluster <= SPELEOTHEM_CLUSTER_HIGH)) return 0;
    precise vec3 spawnPoint = midpoint * SPELEOTHEM_SPAWN_FREQUENCY;
    float spawn = noiseSimplex3(spawnPoint, int(noiseSubstream(seed, 402u)));
    if (!(spawn > SPELEOTHEM_SPAWN_THRESHOLD)) return 0;
    precise float reach = SPELEOTHEM_GROWTH * (spawn - SPELEOTHEM_SPAWN_THRESHOLD) * SPELEOTHEM_REACH_SCALE;
    // std::min(std::max(reach, 0), 1): reach is finite, so GLSL's min and max agree.
    float phi = min(max(reach, 0.0), 1.0);
    precise float halfLength = phi * float(worldCeilingY - worldFloorY - 1) * 0.5;
    return int(ceil(halfLength));
}

// 0.5 + 0.5 * ((length - k) / (length + 1))^taper (voxc::caves::taperDensity).
float speleothemTaperDensity(int k, int length) {
    precise float t = float(length - k) / float(length + 1);
    precise float power = 1.0;
    for (int i = 0; i < SPELEOTHEM_TAPER; ++i) power = power * t;
    precise float density = 0.5 + 0.5 * power;
    return density;
}

// Union with `value` at grid-local voxel `local`, as voxc::combineField's union.
void speleothemWrite(ivec3 local, float value) {
    if (speleothemProtected(push.gridOrigin.xyz + local)) return;
    int address = voxelAddress(local);
    float density = voxels.density[address];
    bool wins = density < value;
    float result = wins ? value : density;
    voxels.density[address] = result;
#ifdef VOXC_MATERIALS
    if (SPELEOTHEM_MATERIAL != 0u && wins && result >= 0.5) materials.material[address] = SPELEOTHEM_MATERIAL;
#endif
}

// The features of the closed runs of `source` (voxc::caves::closedRuns), written into `column`.
// Rock voxels are visited bottom up; each one closes the run above the previous one.
void speleothemGrowFrom(ivec2 source, ivec2 column) {
    int firstWord = speleothemColumnWord(source);
    int floorY = -1; // no rock below yet: air from the grid's bottom is open
    for (int w = 0; w < speleothemWordsPerColumn(); ++w) {
        int valid = min(32, push.gridSize.y - 32 * w);
        uint validBits = valid == 32 ? 0xFFFFFFFFu : (1u << uint(valid)) - 1u;
        uint rock = ~airMask.bits[firstWord + w] & validBits;
        while (rock != 0u) {
            int y = 32 * w + findLSB(rock);
            rock &= rock - 1u;
            int gap = y - floorY - 1;
            if (floorY >= 0 && gap >= SPELEOTHEM_MIN_GAP && gap <= SPELEOTHEM_MAX_GAP) {
                ivec3 world = push.gridOrigin.xyz + ivec3(source.x, 0, source.y);
                int length = speleothemLength(world.x, world.z, world.y + floorY, world.y + y);
                for (int k = 0; k < length; ++k) {
                    float value = speleothemTaperDensity(k, length);
                    if (SPELEOTHEM_KIND != 1) speleothemWrite(ivec3(column.x, y - 1 - k, column.y), value);
                    if (SPELEOTHEM_KIND != 0) speleothemWrite(ivec3(column.x, floorY + 1 + k, column.y), value);
                }
            }
            floorY = y;
        }
    }
}
