#include "GpuMesherCells.h"

#include "voxc/core/Errors.h"
#include "voxc/mesh/MarchingCubes.h"

#include <algorithm>

namespace voxc::vulkan_detail {

namespace {

// Per edge of a cell (edge e runs along axis e / 4 from its lower corner, as the case table
// numbers them): the corner whose cell owns the edge's vertex, and the owner's crossed edges of
// lower axis, which come before the edge's vertex among the owner's (at most two: bit 0 counts
// where the axis is 1 or 2, bit 1 where it is 2).
struct EdgeOwner {
    uint32_t corner, lowerX, lowerY;
};
constexpr std::array<EdgeOwner, 12> edgeOwners() {
    std::array<EdgeOwner, 12> owners{};
    for (uint32_t e = 0; e < 12; ++e) {
        const uint32_t axis = e / 4, along = e % 4, u = (axis + 1) % 3, v = (axis + 2) % 3;
        owners[e] = {(along & 1u) << u | (along >> 1) << v, axis >= 1 ? 1u : 0u, axis == 2 ? 1u : 0u};
    }
    return owners;
}

} // namespace

// Per tile of cells (x fastest): its first cell, grid-local.
std::vector<glm::ivec3> tileFirstCells(glm::ivec3 tileFirst, glm::ivec3 n, const ChunkLayout& layout) {
    std::vector<glm::ivec3> cells;
    cells.reserve(size_t(n.x) * size_t(n.y) * size_t(n.z));
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x) cells.push_back(((tileFirst + glm::ivec3(x, y, z)) << kTileShift) - layout.gridOrigin);
    return cells;
}

std::array<std::array<int8_t, 8>, 256> solidCornerVertices() {
    std::array<std::array<int8_t, 8>, 256> sources;
    const auto& table = marching_cubes::caseTable();
    for (uint32_t mask = 0; mask < 256; ++mask) {
        sources[mask].fill(-1);
        for (uint32_t k = 0; k < uint32_t(table[mask].triangleCount) * 3; ++k) {
            const uint32_t e = table[mask].edges[k], axis = e / 4, along = e % 4, u = (axis + 1) % 3, v = (axis + 2) % 3;
            const uint32_t lower = (along & 1u) << u | (along >> 1) << v, upper = lower | 1u << axis;
            const uint32_t solid = (mask >> lower) & 1u ? lower : upper;
            VOXC_ASSERT(((mask >> solid) & 1u) && !((mask >> (solid ^ lower ^ upper)) & 1u)); // a crossed edge
            if (sources[mask][solid] < 0) sources[mask][solid] = int8_t(k);
        }
    }
    return sources;
}

// The triangles of the active cells [begin, end) (kActiveCellWords each) into `triangles` at each
// cell's first triangle, in the case table's order: each names the vertex of its edges' owners
// (the words the host wrote into `cellInfo` at their slots: owned edges | first vertex << 3). A
// cell finds its neighbours' slots from its own (mc_common.glsl): +1, +8 or +64 within its tile, or
// into the next tile along that axis. A corner cell past the tiles of cells, or in no active tile,
// owns none of the cell's crossed edges, so its word (whatever an earlier mesh left there) is never
// used; its read is kept inside `slots`.
void makeTriangles(const uint32_t* activeCells, size_t begin, size_t end, const uint32_t* cellInfo, size_t slots, glm::ivec3 n,
                   uint32_t* triangles) {
    static constexpr std::array<EdgeOwner, 12> kOwners = edgeOwners();
    const auto& table = marching_cubes::caseTable();
    const uint32_t nextRow = kTileCells * uint32_t(n.x), nextLayer = nextRow * uint32_t(n.y);
    for (size_t i = begin; i < end; ++i) {
        const uint32_t* cell = &activeCells[i * kActiveCellWords];
        const uint32_t slot = cell[0], place = slot % kTileCells, word = cell[3];
        const uint32_t step[3] = {(place & 7u) < 7u ? 1u : kTileCells - 7u, ((place >> 3) & 7u) < 7u ? 8u : nextRow - 56u,
                                  (place >> 6) < 7u ? 64u : nextLayer - 448u};
        uint32_t owners[7];
        for (uint32_t c = 0; c < 7; ++c) {
            const size_t at = size_t(slot) + ((c & 1u) ? step[0] : 0u) + ((c & 2u) ? step[1] : 0u) + ((c & 4u) ? step[2] : 0u);
            owners[c] = cellInfo[std::min(at, slots - 1)];
        }
        const marching_cubes::CellCase& entry = table[(word >> 19) & 0xffu];
        uint32_t* out = &triangles[size_t(cell[2]) * 3];
        for (uint32_t k = 0; k < uint32_t(entry.triangleCount) * 3; ++k) {
            const EdgeOwner& edge = kOwners[entry.edges[k]];
            const uint32_t owner = owners[edge.corner];
            out[k] = (owner >> 3) + (owner & edge.lowerX) + ((owner >> 1) & edge.lowerY);
        }
    }
}

// The second half of orientNormalsToFaces' search, for orientFlaggedNormals: the triangles of each
// flagged vertex in triangle order, found without a pass over every triangle. A vertex's
// triangles are among those of the four cells around its edge (its owner cell, as vertexEdges
// names it, and the cells before it along the other two axes), which are active (their corners
// are on both sides of iso) and so listed in `activeCells` (kActiveCellWords each, in global key
// order, the triangles' order): each is found there by bisection.
void incidentTriangles(const Mesh& mesh, const std::vector<uint8_t>& against, const uint32_t* vertexEdges,
                       const uint32_t* activeCells, uint32_t activeCount, const std::vector<glm::ivec3>& tileCells,
                       std::vector<uint32_t>& incident, std::vector<uint32_t>& triangles) {
    const size_t vertexCount = against.size();
    incident.resize(vertexCount + 1);
    triangles.clear();
    auto before = [](glm::ivec3 a, glm::ivec3 b) { return a.z != b.z ? a.z < b.z : a.y != b.y ? a.y < b.y : a.x < b.x; };
    auto activeIndex = [&](glm::ivec3 cell) {
        uint32_t low = 0, high = activeCount; // the first entry not before `cell`
        while (low < high) {
            const uint32_t middle = low + (high - low) / 2;
            if (before(cellOfSlot(activeCells[size_t(middle) * kActiveCellWords], tileCells), cell))
                low = middle + 1;
            else
                high = middle;
        }
        if (low == activeCount || cellOfSlot(activeCells[size_t(low) * kActiveCellWords], tileCells) != cell)
            throw InternalError("GPU marching cubes: a cell around a vertex's edge is not an active cell");
        return low;
    };
    for (size_t v = 0;; ++v) {
        // To the next flagged vertex, the ones between with no triangles listed.
        const size_t next = size_t(std::find(against.begin() + ptrdiff_t(v), against.end(), uint8_t(1)) - against.begin());
        std::fill(incident.begin() + ptrdiff_t(v), incident.begin() + ptrdiff_t(next) + 1, uint32_t(triangles.size()));
        if (next == vertexCount) break;
        v = next;
        const uint32_t edge = vertexEdges[v], axis = edge >> 30, u = (axis + 1) % 3, w = (axis + 2) % 3;
        const glm::ivec3 owner = cellOfSlot(edge & 0x3fffffffu, tileCells);
        std::array<uint32_t, 4> cells;
        for (uint32_t i = 0; i < 4; ++i) {
            glm::ivec3 cell = owner;
            cell[int(u)] -= int(i & 1u);
            cell[int(w)] -= int(i >> 1);
            cells[i] = activeIndex(cell);
        }
        std::sort(cells.begin(), cells.end());
        for (uint32_t cell : cells) {
            const uint32_t* entry = &activeCells[size_t(cell) * kActiveCellWords];
            for (uint32_t t = entry[2]; t < entry[2] + ((entry[3] >> 3) & 15u); ++t)
                for (size_t k = 0; k < 3; ++k)
                    if (mesh.triangles[size_t(t) * 3 + k] == v) triangles.push_back(t);
        }
    }
}

} // namespace voxc::vulkan_detail
