#pragma once
// A grid of floats that field expressions sample: a 2D height map, `NAME(wx, wz)` for a
// `terrain NAME` or `heightmap NAME` block (bilinear between cell centres, clamped at the edges;
// docs/language.md, "Sampling a terrain", "Heightmaps"), or a 3D volume, `NAME(wp)` for a
// `mesh NAME` block's signed distances (trilinear, clamped; "Meshes"). A field node of kind Map
// holds it; the four things every field operation has live here and in
// compiler/shaders/map_sample.glsl side by side: the checker's rule (two or three float operands,
// a float result), the interpreter's evaluation (sampleMap, sampleVolume), the GLSL (mapSample,
// volumeSample: the same float operations in the same order, every result `precise`, so the two
// agree bit for bit) and the range rule (mapRange, volumeRange).
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace voxc {

struct SampledMap {
    std::string name;       // the block's
    int32_t dimensions = 2; // 2: sampled at (x, z), size.y == 1; 3: at (x, y, z)
    glm::ivec3 size{0};     // cells per axis, each >= 1
    // World position of the corner of cell (0, 0, 0) (y unused by a 2D map), and cells per world
    // voxel along each axis: cell i's centre lies at origin + (i + 0.5) / cellsPerVoxel.
    glm::vec3 origin{0.0f};
    glm::vec3 cellsPerVoxel{1.0f};
    // The value at each cell centre, x fastest, then y, then z (world voxels for a height map,
    // signed distances in world voxels for a volume); empty in a terrain's map as the check makes
    // it, which a run's solve replaces (stages::solveBlocks).
    std::vector<float> values;
    float lowest = 0.0f, highest = 0.0f; // min and max of `values`
    std::string source;                  // the block kind: "terrain", "heightmap" or "mesh"

    float at(int32_t x, int32_t z) const { return values[size_t(z) * size_t(size.x) + size_t(x)]; }
    float at(int32_t x, int32_t y, int32_t z) const {
        return values[(size_t(z) * size_t(size.y) + size_t(y)) * size_t(size.x) + size_t(x)];
    }
};

// The height at world (wx, wz) of a 2D map: with u = (wx - origin.x)·cellsPerVoxel.x - 0.5 (cell
// centre i at u = i), clamped to [0, size.x - 1], cell i = floor(u), weight f = u - i, the
// neighbour min(i + 1, size.x - 1); z alike;
// ((1 - fx)·h00 + fx·h10)·(1 - fz) + ((1 - fx)·h01 + fx·h11)·fz. A NaN coordinate gives NaN; an
// infinite one reads the edge.
float sampleMap(const SampledMap& map, float wx, float wz);

// The value at world (wx, wy, wz) of a 3D map: each axis as sampleMap's, then
// c_yz = (1 - fx)·v(i, ., .) + fx·v(i1, ., .) for the four (y, z) corners,
// c_z = c_0z·(1 - fy) + c_1z·fy, and c_0·(1 - fz) + c_1·fz.
float sampleVolume(const SampledMap& map, float wx, float wy, float wz);

// Bounds of sampleMap over wx in [wxLo, wxHi], wz in [wzLo, wzHi] (lo <= hi, maybe infinite):
// the lowest and highest value of the cells those coordinates read (of the whole map when that
// box is large), widened by the relative rounding of the weighted sum; unbounded for a map not
// solved yet (no values). volumeRange is the same for sampleVolume.
struct MapRange {
    double lo, hi;
};
MapRange mapRange(const SampledMap& map, double wxLo, double wxHi, double wzLo, double wzHi);
MapRange volumeRange(const SampledMap& map, const double lo[3], const double hi[3]);

} // namespace voxc
