#pragma once
// A 2D map that field expressions sample: `NAME(wx, wz)` for a `terrain NAME` block gives the
// height of its eroded ground, in world voxels, bilinear between cell centres and clamped at the
// edges (docs/language.md, "Sampling a terrain"). A field node of kind Map holds it; the four
// things every field operation has live here and in compiler/shaders/map_sample.glsl side by side:
// the checker's rule (two float operands, a float result), the interpreter's evaluation
// (sampleMap), the GLSL (map_sample.glsl's mapSample, the same float operations in the same order,
// every result `precise`, so the two agree bit for bit) and the range rule (mapRange).
#include <cstdint>
#include <string>
#include <vector>

namespace voxc {

struct SampledMap {
    std::string name;          // the terrain block's
    int32_t side = 0;          // cells per side (a power of two)
    float originX = 0.0f;      // world x, z of the corner of cell (0, 0)
    float originZ = 0.0f;
    float cellsPerVoxel = 1.0f; // 1 / cell size
    // World y of the ground at each cell centre, x fastest, then z (side * side values); empty in
    // the map the check makes, which a run's solve replaces (stages::solveBlocks).
    std::vector<float> height;
    float lowest = 0.0f, highest = 0.0f; // min and max of `height`

    float at(int32_t x, int32_t z) const { return height[size_t(z) * size_t(side) + size_t(x)]; }
};

// The height at world (wx, wz): with u = (wx - originX)·cellsPerVoxel - 0.5 (cell centre i at
// u = i), clamped to [0, side - 1], cell i = floor(u), weight f = u - i, the neighbour
// min(i + 1, side - 1); z alike; ((1 - fx)·h00 + fx·h10)·(1 - fz) + ((1 - fx)·h01 + fx·h11)·fz.
// A NaN coordinate gives NaN; an infinite one reads the edge.
float sampleMap(const SampledMap& map, float wx, float wz);

// Bounds of sampleMap over wx in [wxLo, wxHi], wz in [wzLo, wzHi] (lo <= hi, maybe infinite):
// the lowest and highest height of the cells those coordinates read (of the whole map when that
// box is large), widened by the relative rounding of the weighted sum; unbounded for a map not
// solved yet (no heights).
struct MapRange {
    double lo, hi;
};
MapRange mapRange(const SampledMap& map, double wxLo, double wxHi, double wzLo, double wzHi);

} // namespace voxc
