#pragma once
// One chunk's share of surface nets: the vertices of its cells and the quads of the grid edges
// it owns, both keyed by global cell so that chunks merge without seams.
#include "voxc/grid/Grid.h"

#include <cstdint>
#include <glm/vector_relational.hpp>
#include <vector>

namespace voxc::surface_nets {

// Cells are named by their minimum corner in grid-local coordinates. The cell domain runs from
// -1 to gridSize-1 on each axis so that the air outside the grid closes the surface.
struct CellDomain {
    glm::ivec3 gridSize;
    uint64_t key(glm::ivec3 cell) const {
        const uint64_t nx = uint64_t(gridSize.x) + 1, ny = uint64_t(gridSize.y) + 1;
        return uint64_t(cell.x + 1) + nx * (uint64_t(cell.y + 1) + ny * uint64_t(cell.z + 1));
    }
};

struct CellVertex {
    uint64_t cell;
    glm::vec3 position;
    glm::vec3 normal; // zero when the field gradient vanishes; the merge fills it from the faces
    uint8_t material;  // most common among the cell's solid corners, ties to the lowest id
};

// The quad around a crossed grid edge, which starts at the minimum corner of `cells[2]`.
// `cells` are counter-clockwise seen from the air side.
struct EdgeQuad {
    uint64_t edge; // cell key * 3 + axis: a global, chunk-independent order
    uint64_t cells[4];
    uint8_t material; // of the edge's solid voxel
};

struct ChunkSurface {
    std::vector<CellVertex> vertices;
    std::vector<EdgeQuad> quads;
};

// Grid-local cells [begin, end) whose minimum corner lies in world chunk `worldChunk`; empty
// (some begin >= end) when the chunk holds no cell.
struct CellRange {
    glm::ivec3 begin, end;
    bool empty() const { return glm::any(glm::greaterThanEqual(begin, end)); }
};
CellRange chunkCells(const ChunkLayout& layout, glm::ivec3 worldChunk);

// True when every voxel the cells read (their corners, [begin, end] inclusive, outside the grid
// air) is on one side of iso: then no cell is crossed and the chunk has no surface.
bool cellsAreUniform(const ChunkedGrid& grid, float iso, const CellRange& cells);

// Extracts the cells whose minimum corner lies in world chunk `worldChunk` of the grid's layout.
ChunkSurface extractChunk(const ChunkedGrid& grid, float iso, glm::ivec3 worldChunk);

} // namespace voxc::surface_nets
