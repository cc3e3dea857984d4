// Sampling a terrain's height map from a field (voxc/program/SampledMap.h): voxc::sampleMap's
// float operations in the same order, every result `precise`, so both backends agree bit for bit.
// The map is a solve table of binding 12 (solve_tables.glsl, included before this file) with
// min 0 and size (side, 1, side), its heights where a table keeps densities; the field kernel
// passes the map's corner and cells per voxel as literals.

float mapSampleClamp(float u, float last) { return u < 0.0 ? 0.0 : (u > last ? last : u); }

float mapSampleAt(int heights, int side, int x, int z) {
    return intBitsToFloat(solveTables.words[heights + z * side + x]);
}

float mapSample(int table, float originX, float originZ, float cellsPerVoxel, float wx, float wz) {
    if (mathIsNan(wx) || mathIsNan(wz)) return uintBitsToFloat(0x7FC00000u);
    int start = solveTableStart(table);
    int side = solveTableSize(start).x;
    int heights = start + 6;
    float last = float(side - 1);
    precise float du = wx - originX;
    precise float su = du * cellsPerVoxel;
    precise float u = mapSampleClamp(su - 0.5, last);
    precise float dv = wz - originZ;
    precise float sv = dv * cellsPerVoxel;
    precise float v = mapSampleClamp(sv - 0.5, last);
    float cellU = floor(u), cellV = floor(v);
    int i = int(cellU), j = int(cellV);
    int i1 = min(i + 1, side - 1), j1 = min(j + 1, side - 1);
    precise float tx = u - cellU;
    precise float tz = v - cellV;
    precise float sx = 1.0 - tx;
    precise float sz = 1.0 - tz;
    precise float near = sx * mapSampleAt(heights, side, i, j) + tx * mapSampleAt(heights, side, i1, j);
    precise float far = sx * mapSampleAt(heights, side, i, j1) + tx * mapSampleAt(heights, side, i1, j1);
    precise float result = near * sz + far * tz;
    return result;
}
