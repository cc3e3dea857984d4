#include "voxc/mesh/SurfaceNets.h"

#include "CellExtraction.h"
#include "ChunkWorkers.h"
#include "voxc/core/Errors.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace voxc {
namespace {

using surface_nets::CellVertex;
using surface_nets::ChunkSurface;
using surface_nets::EdgeQuad;

// Chunks are independent, so workers take them in any order; each result has its own slot.
std::vector<ChunkSurface> extractAll(const ChunkedGrid& grid, const MeshOptions& options, const std::vector<glm::ivec3>& chunks,
                                     MeshStats& stats) {
    std::vector<ChunkSurface> surfaces(chunks.size());
    stats.skippedChunks = forEachChunk(chunks.size(), [&](size_t i) {
        if (options.skipUniformChunks &&
            surface_nets::cellsAreUniform(grid, options.iso, surface_nets::chunkCells(grid.layout(), chunks[i])))
            return false;
        surfaces[i] = surface_nets::extractChunk(grid, options.iso, chunks[i]);
        return true;
    });
    stats.chunks = chunks.size();
    return surfaces;
}

} // namespace

Mesh meshSurfaceNets(const ChunkedGrid& grid, float iso) { return meshSurfaceNets(grid, MeshOptions{.iso = iso}); }

Mesh meshSurfaceNets(const ChunkedGrid& grid, const MeshOptions& options, MeshStats* stats) {
    MeshStats counted;
    const std::vector<ChunkSurface> surfaces = extractAll(grid, options, cellChunks(grid.layout()), counted);
    if (stats) *stats = counted;

    // Ordering by global cell and edge makes the result independent of the chunking.
    std::vector<CellVertex> vertices;
    std::vector<EdgeQuad> quads;
    for (const ChunkSurface& s : surfaces) {
        vertices.insert(vertices.end(), s.vertices.begin(), s.vertices.end());
        quads.insert(quads.end(), s.quads.begin(), s.quads.end());
    }
    std::sort(vertices.begin(), vertices.end(), [](const CellVertex& a, const CellVertex& b) { return a.cell < b.cell; });
    std::sort(quads.begin(), quads.end(), [](const EdgeQuad& a, const EdgeQuad& b) { return a.edge < b.edge; });
    VOXC_ASSERT(vertices.size() <= UINT32_MAX);

    Mesh mesh;
    std::vector<uint64_t> cellKeys;
    mesh.positions.reserve(vertices.size());
    mesh.normals.reserve(vertices.size());
    mesh.vertexMaterials.reserve(vertices.size());
    cellKeys.reserve(vertices.size());
    for (const CellVertex& v : vertices) {
        mesh.positions.push_back(v.position);
        mesh.normals.push_back(v.normal);
        mesh.vertexMaterials.push_back(v.material);
        cellKeys.push_back(v.cell);
    }
    auto vertexOf = [&](uint64_t cell) {
        const auto it = std::lower_bound(cellKeys.begin(), cellKeys.end(), cell);
        VOXC_ASSERT(it != cellKeys.end() && *it == cell); // every cell around a crossed edge is crossed
        return uint32_t(it - cellKeys.begin());
    };
    mesh.triangles.reserve(quads.size() * 6);
    mesh.triangleMaterials.reserve(quads.size() * 2);
    for (const EdgeQuad& q : quads) {
        const uint32_t v[4] = {vertexOf(q.cells[0]), vertexOf(q.cells[1]), vertexOf(q.cells[2]), vertexOf(q.cells[3])};
        mesh.triangles.insert(mesh.triangles.end(), {v[0], v[1], v[2], v[0], v[2], v[3]});
        mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), {q.material, q.material});
    }
    orientNormalsToFaces(mesh); // vanished gradients, and gradients across thin features
    return mesh;
}

} // namespace voxc
