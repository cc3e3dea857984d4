// Sampling a height map or a volume from a field (voxc/program/SampledMap.h): voxc::sampleMap's
// and voxc::sampleVolume's float operations in the same order, every result `precise`, so both
// backends agree bit for bit. The map is a solve table of binding 12 (solve_tables.glsl, included
// before this file) with min 0 and size (width, 1, depth) or (x, y, z), its values where a table
// keeps densities; the field kernel passes the map's corner and cells per voxel as literals.

float mapSampleClamp(float u, float last) { return u < 0.0 ? 0.0 : (u > last ? last : u); }

float mapSampleAt(int values, ivec3 size, int x, int y, int z) {
    return intBitsToFloat(solveTables.words[values + (z * size.y + y) * size.x + x]);
}

// One axis: u = clamp((w - origin)·cellsPerVoxel - 0.5, 0, cells - 1); returns the weight of the
// neighbour, `cell` and `next` the two cells read.
float mapSampleAxis(float w, float origin, float cellsPerVoxel, int cells, out int cell, out int next) {
    precise float d = w - origin;
    precise float s = d * cellsPerVoxel;
    precise float u = mapSampleClamp(s - 0.5, float(cells - 1));
    float floored = floor(u);
    cell = int(floored);
    next = min(cell + 1, cells - 1);
    precise float t = u - floored;
    return t;
}

float mapSample(int table, float originX, float originZ, float cellsPerVoxelX, float cellsPerVoxelZ, float wx,
                float wz) {
    if (mathIsNan(wx) || mathIsNan(wz)) return uintBitsToFloat(0x7FC00000u);
    int start = solveTableStart(table);
    ivec3 size = solveTableSize(start);
    int values = start + 6;
    int i, i1, j, j1;
    precise float tx = mapSampleAxis(wx, originX, cellsPerVoxelX, size.x, i, i1);
    precise float tz = mapSampleAxis(wz, originZ, cellsPerVoxelZ, size.z, j, j1);
    precise float sx = 1.0 - tx;
    precise float sz = 1.0 - tz;
    precise float near = sx * mapSampleAt(values, size, i, 0, j) + tx * mapSampleAt(values, size, i1, 0, j);
    precise float far = sx * mapSampleAt(values, size, i, 0, j1) + tx * mapSampleAt(values, size, i1, 0, j1);
    precise float result = near * sz + far * tz;
    return result;
}

float volumeSample(int table, vec3 origin, vec3 cellsPerVoxel, float wx, float wy, float wz) {
    if (mathIsNan(wx) || mathIsNan(wy) || mathIsNan(wz)) return uintBitsToFloat(0x7FC00000u);
    int start = solveTableStart(table);
    ivec3 size = solveTableSize(start);
    int values = start + 6;
    int i, i1, j, j1, k, k1;
    precise float tx = mapSampleAxis(wx, origin.x, cellsPerVoxel.x, size.x, i, i1);
    precise float ty = mapSampleAxis(wy, origin.y, cellsPerVoxel.y, size.y, j, j1);
    precise float tz = mapSampleAxis(wz, origin.z, cellsPerVoxel.z, size.z, k, k1);
    precise float sx = 1.0 - tx;
    precise float sy = 1.0 - ty;
    precise float sz = 1.0 - tz;
    precise float c00 = sx * mapSampleAt(values, size, i, j, k) + tx * mapSampleAt(values, size, i1, j, k);
    precise float c10 = sx * mapSampleAt(values, size, i, j1, k) + tx * mapSampleAt(values, size, i1, j1, k);
    precise float c01 = sx * mapSampleAt(values, size, i, j, k1) + tx * mapSampleAt(values, size, i1, j, k1);
    precise float c11 = sx * mapSampleAt(values, size, i, j1, k1) + tx * mapSampleAt(values, size, i1, j1, k1);
    precise float c0 = c00 * sy + c10 * ty;
    precise float c1 = c01 * sy + c11 * ty;
    precise float result = c0 * sz + c1 * tz;
    return result;
}
