// The solve tables (binding 12, voxc::solveTableWords): word 0 the table count, then each
// table's first word; a table is min.xyz, size.xyz (grid-local voxels), its densities as float
// bits (x fastest, then y, then z), then, when it has them, one material id per cell.
layout(std430, set = 0, binding = 12) readonly buffer SolveTables {
    int words[];
} solveTables;

int solveTableStart(int table) { return solveTables.words[1 + table]; }
ivec3 solveTableMin(int start) {
    return ivec3(solveTables.words[start], solveTables.words[start + 1], solveTables.words[start + 2]);
}
ivec3 solveTableSize(int start) {
    return ivec3(solveTables.words[start + 3], solveTables.words[start + 4], solveTables.words[start + 5]);
}
