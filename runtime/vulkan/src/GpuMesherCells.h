#pragma once
// The device mesher's host half over its active cells (docs/architecture.md, "On the device"):
// where a slot's cell is, the triangles made from the cells' words, the majority-material vote
// from the vertices' materials and the mapped material words, and the normals' incident search.
#include "voxc/grid/Grid.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/mesh/Mesh.h"

#include <glm/vec3.hpp>
#include <glm/vector_relational.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace voxc::vulkan_detail {

constexpr int kTileShift = 3; // tiles of 8^3 cells (mc_common.glsl)
constexpr uint32_t kTileSide = 1u << kTileShift;
constexpr uint32_t kTileCells = kTileSide * kTileSide * kTileSide;
constexpr uint32_t kActiveCellWords = 4; // slot, first vertex, first triangle, cell word (mc_materials.glsl)

// Per tile of cells (x fastest): its first cell, grid-local.
std::vector<glm::ivec3> tileFirstCells(glm::ivec3 tileFirst, glm::ivec3 n, const ChunkLayout& layout);

// The grid-local cell at `slot` (mc_common.glsl, cellOfSlot), from tileFirstCells.
inline glm::ivec3 cellOfSlot(uint32_t slot, const std::vector<glm::ivec3>& tileCells) {
    const uint32_t place = slot % kTileCells;
    return tileCells[slot / kTileCells] + glm::ivec3(int(place % kTileSide), int(place / kTileSide % kTileSide), int(place / (kTileSide * kTileSide)));
}

// Per case, per corner: the first of the case's triangle corners (k of triangleCount * 3) whose
// edge ends at that corner where it is solid, or -1 where none does (a solid corner whose
// neighbours along the cell's edges are all solid).
std::array<std::array<int8_t, 8>, 256> solidCornerVertices();

// The majority-material vote on the host (mc_materials.glsl's, the CPU mesher's): the most common
// id among a cell's solid corners (0 outside the grid); ties go to the lowest. A solid corner at
// the end of one of the cell's crossed edges takes the material of that edge's vertex (the
// material of its solid sample, read where the device read the sample); the others are read from
// the executor's mapped material words (a uint per voxel, the id in its low byte, at
// ChunkLayout::address).
class HostVote {
public:
    HostVote(const uint32_t* words, const ChunkLayout& layout, const std::vector<glm::ivec3>& tileCells)
        : words_(words), layout_(layout), tileCells_(tileCells) {}

    // `cell`: the active cell's words; `triangles`: its triangles' vertex indices.
    uint8_t operator()(const uint32_t* cell, const uint32_t* triangles, const uint8_t* vertexMaterials) const {
        static const std::array<std::array<int8_t, 8>, 256> kSources = solidCornerVertices();
        const uint32_t solid = (cell[3] >> 19) & 0xffu;
        const std::array<int8_t, 8>& source = kSources[solid];
        uint8_t ids[8];
        int count = 0;
        for (uint32_t c = 0; c < 8; ++c) {
            if (((solid >> c) & 1u) == 0) continue;
            ids[count++] = source[c] >= 0 ? vertexMaterials[triangles[source[c]]] : read(cell[0], c);
        }
        return marching_cubes::mostCommonMaterial(ids, count);
    }

private:
    uint8_t read(uint32_t slot, uint32_t corner) const {
        const glm::ivec3 p = cellOfSlot(slot, tileCells_) + glm::ivec3(int(corner & 1u), int((corner >> 1) & 1u), int(corner >> 2));
        const bool inside = glm::all(glm::greaterThanEqual(p, glm::ivec3(0))) && glm::all(glm::lessThan(p, layout_.gridSize));
        return inside ? uint8_t(words_[layout_.address(p)]) : 0;
    }

    const uint32_t* words_;
    const ChunkLayout& layout_;
    const std::vector<glm::ivec3>& tileCells_;
};

// The triangles of the active cells [begin, end) (kActiveCellWords each) into `triangles` at each
// cell's first triangle, in the case table's order: each names the vertex of its edges' owners
// (the words the host wrote into `cellInfo` at their slots: owned edges | first vertex << 3). A
// cell finds its neighbours' slots from its own (mc_common.glsl): +1, +8 or +64 within its tile, or
// into the next tile along that axis. A corner cell past the tiles of cells, or in no active tile,
// owns none of the cell's crossed edges, so its word (whatever an earlier mesh left there) is never
// used; its read is kept inside `slots`.
void makeTriangles(const uint32_t* activeCells, size_t begin, size_t end, const uint32_t* cellInfo, size_t slots, glm::ivec3 n,
                   uint32_t* triangles);

// The second half of orientNormalsToFaces' search, for orientFlaggedNormals: the triangles of each
// flagged vertex in triangle order, found without a pass over every triangle. A vertex's
// triangles are among those of the four cells around its edge (its owner cell, as vertexEdges
// names it, and the cells before it along the other two axes), which are active (their corners
// are on both sides of iso) and so listed in `activeCells` (kActiveCellWords each, in global key
// order, the triangles' order): each is found there by bisection.
void incidentTriangles(const Mesh& mesh, const std::vector<uint8_t>& against, const uint32_t* vertexEdges,
                       const uint32_t* activeCells, uint32_t activeCount, const std::vector<glm::ivec3>& tileCells,
                       std::vector<uint32_t>& incident, std::vector<uint32_t>& triangles);

} // namespace voxc::vulkan_detail
