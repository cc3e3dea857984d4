#pragma once
// Density fields for the mesh tests, built in world coordinates so one shape can be placed
// at any origin.
#include "voxc/grid/Grid.h"

#include <functional>
#include <glm/geometric.hpp>
#include <random>

namespace voxc::test {

inline ChunkedGrid makeGrid(glm::ivec3 origin, glm::ivec3 size, int32_t chunkSize, const std::function<float(glm::vec3)>& density) {
    ChunkedGrid grid(ChunkLayout::make(origin, size, chunkSize));
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) grid.at({x, y, z}) = density(glm::vec3(origin + glm::ivec3(x, y, z)));
    return grid;
}

// Sets every voxel's material from its world position.
inline void paintMaterials(ChunkedGrid& grid, const std::function<uint8_t(glm::ivec3)>& material) {
    const ChunkLayout& layout = grid.layout();
    for (int z = 0; z < layout.gridSize.z; ++z)
        for (int y = 0; y < layout.gridSize.y; ++y)
            for (int x = 0; x < layout.gridSize.x; ++x) grid.materialAt({x, y, z}) = material(layout.gridOrigin + glm::ivec3(x, y, z));
}

// Densities uniform in [0, 1] per voxel, from `seed`: sheets and ridges one voxel thin everywhere,
// and almost every cell face with four crossings ambiguous.
inline ChunkedGrid noiseGrid(glm::ivec3 origin, glm::ivec3 size, int32_t chunkSize, unsigned seed) {
    ChunkedGrid grid(ChunkLayout::make(origin, size, chunkSize));
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) grid.at({x, y, z}) = unit(random);
    return grid;
}

// Four materials in diagonal stripes of world position.
inline uint8_t stripeMaterial(glm::ivec3 p) { return uint8_t(1 + unsigned(p.x * 7 + p.y * 3 + p.z) % 4); }

// Falls linearly from 1 at the centre to 0 at `falloff`, so the iso-level t sits at radius falloff*(1-t).
inline std::function<float(glm::vec3)> coneBall(glm::vec3 centre, float falloff) {
    return [=](glm::vec3 p) { return glm::max(0.0f, 1.0f - glm::length(p - centre) / falloff); };
}

// 1 inside the half-open world box [lo, hi), 0 outside.
inline std::function<float(glm::vec3)> box(glm::vec3 lo, glm::vec3 hi) {
    return [=](glm::vec3 p) { return glm::all(glm::greaterThanEqual(p, lo)) && glm::all(glm::lessThan(p, hi)) ? 1.0f : 0.0f; };
}

} // namespace voxc::test
