// The air voxels of the grid before a speleothem stage, one bit each, in voxc::caves::AirMask's
// layout: column (x, z) owns words (x + gridSize.x * z) * wordsPerColumn onward, voxel y is bit
// y % 32 of word y / 32. Lives in the scratch buffer (kBindingScratch, StagePlan::scratchWords).

layout(std430, set = 0, binding = 11) buffer SpeleothemAirMask {
    uint bits[];
} airMask;

int speleothemWordsPerColumn() { return (push.gridSize.y + 31) / 32; }

int speleothemColumnWord(ivec2 column) {
    return (column.x + push.gridSize.x * column.y) * speleothemWordsPerColumn();
}
