#include "voxc/mesh/MarchingCubes.h"

#include "CellExtraction.h"
#include "ChunkWorkers.h"
#include "voxc/core/Errors.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>

namespace voxc::marching_cubes {
namespace {

using surface_nets::CellDomain;
using surface_nets::CellRange;

// Densities and materials of a chunk's cells plus one sample on every side for the
// central-difference gradients. Non-finite densities and the outside of the grid read 0, as
// surface nets and the uniform-chunk scan read them.
class Samples {
public:
    Samples(const ChunkedGrid& grid, glm::ivec3 first, glm::ivec3 extent) : first_(first), extent_(extent) {
        const glm::ivec3 size = grid.layout().gridSize;
        values_.resize(size_t(extent.x) * size_t(extent.y) * size_t(extent.z));
        materials_.resize(values_.size());
        size_t i = 0;
        for (int z = 0; z < extent.z; ++z)
            for (int y = 0; y < extent.y; ++y)
                for (int x = 0; x < extent.x; ++x, ++i) {
                    const glm::ivec3 p = first + glm::ivec3(x, y, z);
                    if (glm::any(glm::lessThan(p, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(p, size))) continue;
                    const float d = grid.at(p);
                    values_[i] = std::isfinite(d) ? d : 0.0f;
                    materials_[i] = grid.materialAt(p);
                }
    }
    float at(glm::ivec3 p) const { return values_[index(p)]; }
    uint8_t materialAt(glm::ivec3 p) const { return materials_[index(p)]; }
    // Flat access for the hot loops: index(p) + offset(d) is the sample at p + d.
    size_t index(glm::ivec3 p) const {
        const glm::ivec3 q = p - first_;
        return size_t(q.x) + size_t(extent_.x) * (size_t(q.y) + size_t(extent_.y) * size_t(q.z));
    }
    ptrdiff_t offset(glm::ivec3 d) const { return d.x + ptrdiff_t(extent_.x) * (d.y + ptrdiff_t(extent_.y) * d.z); }
    float atIndex(size_t i) const { return values_[i]; }
    glm::vec3 gradient(glm::ivec3 p) const {
        return 0.5f * glm::vec3(at(p + glm::ivec3(1, 0, 0)) - at(p - glm::ivec3(1, 0, 0)),
                                at(p + glm::ivec3(0, 1, 0)) - at(p - glm::ivec3(0, 1, 0)),
                                at(p + glm::ivec3(0, 0, 1)) - at(p - glm::ivec3(0, 0, 1)));
    }

private:
    glm::ivec3 first_, extent_;
    std::vector<float> values_;
    std::vector<uint8_t> materials_;
};

glm::ivec3 axisStep(int axis) {
    glm::ivec3 step(0);
    step[axis] = 1;
    return step;
}

EdgeVertex edgeVertex(const Samples& samples, glm::ivec3 lower, int axis, float iso, float margin, glm::ivec3 gridOrigin) {
    const glm::ivec3 upper = lower + axisStep(axis);
    const float d0 = samples.at(lower), d1 = samples.at(upper);
    const float t = crossing(d0, d1, iso, margin);
    glm::vec3 position(gridOrigin + lower);
    position[axis] += t;
    const glm::vec3 gradient = (1.0f - t) * samples.gradient(lower) + t * samples.gradient(upper);
    const float length = glm::length(gradient);
    glm::vec3 normal;
    if (length > 0.0f && std::isfinite(length)) {
        normal = -gradient / length;
    } else {
        normal = glm::vec3(0.0f); // from the solid sample to the air one
        normal[axis] = d0 > iso ? 1.0f : -1.0f;
    }
    const uint8_t material = samples.materialAt(d0 > iso ? lower : upper);
    return {0, position, normal, material};
}

// The most common material among the solid corners; ties go to the lowest id.
uint8_t majorityMaterial(const Samples& samples, glm::ivec3 cell, unsigned solid) {
    int votes[256] = {};
    uint8_t best = kMaterialNone;
    for (int c = 0; c < 8; ++c) {
        if (!((solid >> c) & 1u)) continue;
        const uint8_t m = samples.materialAt(cell + cornerOffset(c));
        ++votes[m];
        if (votes[m] > votes[best] || (votes[m] == votes[best] && m < best)) best = m;
    }
    return best;
}

// The share of the cells `cells` (grid-local, inside the cell domain): what extractChunk does for
// one chunk's cells, and the mesh of a box of cells for one chunk's part of the box.
ChunkMesh extractCells(const ChunkedGrid& grid, float iso, const CellRange& cells, float margin) {
    const ChunkLayout& layout = grid.layout();
    const CellDomain domain{layout.gridSize};
    ChunkMesh mesh;
    if (cells.empty()) return mesh;
    const Samples samples(grid, cells.begin - 1, cells.end - cells.begin + 3);

    // Every crossed edge of the chunk's cells: lower corners in [begin, end] (the high faces
    // included), but along its own axis an edge starting at `end` belongs to no cell here.
    const ptrdiff_t axisOffset[3] = {samples.offset(axisStep(0)), samples.offset(axisStep(1)), samples.offset(axisStep(2))};
    for (int z = cells.begin.z; z <= cells.end.z; ++z)
        for (int y = cells.begin.y; y <= cells.end.y; ++y)
            for (int x = cells.begin.x; x <= cells.end.x; ++x) {
                const glm::ivec3 lower(x, y, z);
                const size_t at = samples.index(lower);
                const bool solid = samples.atIndex(at) > iso;
                for (int axis = 0; axis < 3; ++axis) {
                    if (lower[axis] == cells.end[axis]) continue;
                    if (solid == (samples.atIndex(size_t(ptrdiff_t(at) + axisOffset[axis])) > iso)) continue;
                    EdgeVertex v = edgeVertex(samples, lower, axis, iso, margin, layout.gridOrigin);
                    v.edge = domain.key(lower) * 3 + uint64_t(axis);
                    mesh.vertices.push_back(v);
                }
            }

    const std::array<CellCase, 256>& table = caseTable();
    ptrdiff_t cornerOffsets[8];
    for (int c = 0; c < 8; ++c) cornerOffsets[c] = samples.offset(cornerOffset(c));
    // Edge e of a cell as an offset from the cell's key times 3 (keys are linear in the corner).
    int64_t edgeKeyOffsets[12];
    for (int e = 0; e < 12; ++e) {
        const glm::ivec3 d = cornerOffset(edgeCorners(e)[0]);
        edgeKeyOffsets[e] = int64_t(domain.key(d) - domain.key(glm::ivec3(0))) * 3 + edgeAxis(e);
    }
    for (int z = cells.begin.z; z < cells.end.z; ++z)
        for (int y = cells.begin.y; y < cells.end.y; ++y)
            for (int x = cells.begin.x; x < cells.end.x; ++x) {
                const glm::ivec3 cell(x, y, z);
                const size_t at = samples.index(cell);
                unsigned solid = 0;
                for (int c = 0; c < 8; ++c)
                    if (samples.atIndex(size_t(ptrdiff_t(at) + cornerOffsets[c])) > iso) solid |= 1u << c;
                const CellCase& cellCase = table[solid];
                if (cellCase.triangleCount == 0) continue;
                const uint64_t cellKey = domain.key(cell);
                const uint8_t material = majorityMaterial(samples, cell, solid);
                for (int t = 0; t < cellCase.triangleCount; ++t) {
                    CellTriangle triangle{cellKey, {}, material};
                    for (int k = 0; k < 3; ++k) {
                        const int edge = cellCase.edges[size_t(t * 3 + k)];
                        triangle.edges[size_t(k)] = uint64_t(int64_t(cellKey * 3) + edgeKeyOffsets[edge]);
                    }
                    mesh.triangles.push_back(triangle);
                }
            }
    return mesh;
}

} // namespace

ChunkMesh extractChunk(const ChunkedGrid& grid, float iso, glm::ivec3 worldChunk) {
    return extractCells(grid, iso, surface_nets::chunkCells(grid.layout(), worldChunk), crossingMargin(grid.layout()));
}

} // namespace voxc::marching_cubes

namespace voxc {

using marching_cubes::ChunkMesh;
using marching_cubes::EdgeVertex;

namespace {

bool sameBits(const EdgeVertex& a, const EdgeVertex& b) {
    return std::memcmp(&a.position, &b.position, sizeof a.position) == 0 && std::memcmp(&a.normal, &b.normal, sizeof a.normal) == 0 &&
           a.material == b.material;
}

} // namespace

Mesh meshMarchingCubes(const ChunkedGrid& grid, const MeshOptions& options, MeshStats* stats) {
    const ChunkLayout& layout = grid.layout();
    return meshMarchingCubesCells(grid, {glm::ivec3(-1), layout.gridSize}, marching_cubes::crossingMargin(layout), options,
                                  stats);
}

Mesh meshMarchingCubesCells(const ChunkedGrid& grid, const CellBox& cells, float margin, const MeshOptions& options,
                            MeshStats* stats) {
    const std::vector<glm::ivec3> chunks = cellChunks(grid.layout());
    std::vector<ChunkMesh> parts(chunks.size());
    const size_t skipped = forEachChunk(chunks.size(), [&](size_t i) {
        const surface_nets::CellRange chunk = surface_nets::chunkCells(grid.layout(), chunks[i]);
        const surface_nets::CellRange share{glm::max(chunk.begin, cells.begin), glm::min(chunk.end, cells.end)};
        if (share.empty() || (options.skipUniformChunks && surface_nets::cellsAreUniform(grid, options.iso, share)))
            return false;
        parts[i] = marching_cubes::extractCells(grid, options.iso, share, margin);
        return true;
    });
    if (stats) *stats = MeshStats{chunks.size(), skipped};
    return marching_cubes::mergeChunks(std::move(parts));
}

Mesh marching_cubes::mergeChunks(std::vector<ChunkMesh> parts) {
    // Global edge and cell order makes the result independent of the chunking. Edges on a chunk
    // face come from both chunks; they must agree bit for bit (the same samples, the same code).
    std::vector<EdgeVertex> vertices;
    std::vector<marching_cubes::CellTriangle> triangles;
    for (const ChunkMesh& part : parts) {
        vertices.insert(vertices.end(), part.vertices.begin(), part.vertices.end());
        triangles.insert(triangles.end(), part.triangles.begin(), part.triangles.end());
    }
    parts.clear();
    std::stable_sort(vertices.begin(), vertices.end(), [](const EdgeVertex& a, const EdgeVertex& b) { return a.edge < b.edge; });
    std::stable_sort(triangles.begin(), triangles.end(), [](const auto& a, const auto& b) { return a.cell < b.cell; });
    size_t unique = 0;
    for (size_t i = 0; i < vertices.size(); ++i) {
        if (unique > 0 && vertices[unique - 1].edge == vertices[i].edge) {
            if (!sameBits(vertices[unique - 1], vertices[i]))
                throw InternalError("marching cubes: two chunks computed different vertices for one grid edge");
            continue;
        }
        vertices[unique++] = vertices[i];
    }
    vertices.resize(unique);
    VOXC_ASSERT(vertices.size() <= UINT32_MAX);

    Mesh mesh;
    mesh.positions.reserve(vertices.size());
    mesh.normals.reserve(vertices.size());
    mesh.vertexMaterials.reserve(vertices.size());
    for (const EdgeVertex& v : vertices) {
        mesh.positions.push_back(v.position);
        mesh.normals.push_back(v.normal);
        mesh.vertexMaterials.push_back(v.material);
    }
    auto vertexOf = [&](uint64_t edge) {
        const auto it = std::lower_bound(vertices.begin(), vertices.end(), edge, [](const EdgeVertex& v, uint64_t e) { return v.edge < e; });
        VOXC_ASSERT(it != vertices.end() && it->edge == edge); // a cell uses only crossed edges
        return uint32_t(it - vertices.begin());
    };
    mesh.triangles.reserve(triangles.size() * 3);
    mesh.triangleMaterials.reserve(triangles.size());
    for (const auto& t : triangles) {
        for (uint64_t edge : t.edges) mesh.triangles.push_back(vertexOf(edge));
        mesh.triangleMaterials.push_back(t.material);
    }
    return mesh;
}

} // namespace voxc
