#pragma once
// One chunk's share of surface nets: the vertices of its cells and the quads of the grid edges
// it owns, both keyed by global cell so that chunks merge without seams.
#include "voxc/grid/Grid.h"

#include <cstdint>
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
};

// The quad around a crossed grid edge, which starts at the minimum corner of `cells[2]`.
// `cells` are counter-clockwise seen from the air side.
struct EdgeQuad {
    uint64_t edge; // cell key * 3 + axis: a global, chunk-independent order
    uint64_t cells[4];
};

struct ChunkSurface {
    std::vector<CellVertex> vertices;
    std::vector<EdgeQuad> quads;
};

// Extracts the cells whose minimum corner lies in world chunk `worldChunk` of the grid's layout.
ChunkSurface extractChunk(const ChunkedGrid& grid, float iso, glm::ivec3 worldChunk);

} // namespace voxc::surface_nets
