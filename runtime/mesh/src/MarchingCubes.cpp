#include "voxc/mesh/MarchingCubes.h"

#include "CellExtraction.h"
#include "ChunkWorkers.h"
#include "SignBits.h"
#include "voxc/core/Errors.h"
#include "voxc/core/HugePages.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <memory>
#include <thread>

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

// Samples is a chunk's gathered block, SampleReader reads the grid in place: both return the same
// densities, so a vertex has the same bits from either.
template <class SampleSource>
EdgeVertex edgeVertex(const SampleSource& samples, glm::ivec3 lower, int axis, float iso, float margin, glm::ivec3 gridOrigin) {
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
template <class SampleSource> uint8_t majorityMaterial(const SampleSource& samples, glm::ivec3 cell, unsigned solid) {
    uint8_t materials[8];
    int count = 0;
    for (int c = 0; c < 8; ++c)
        if ((solid >> c) & 1u) materials[count++] = samples.materialAt(cell + cornerOffset(c));
    return mostCommonMaterial(materials, count);
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


// The grid's samples read in place, as Samples reads its gathered copy: outside the grid and not
// finite read 0, outside has no material.
class SampleReader {
public:
    explicit SampleReader(const ChunkedGrid& grid)
        : layout_(grid.layout()), densities_(grid.data().data()), materials_(grid.materials().data()) {}
    float at(glm::ivec3 p) const {
        if (!inside(p)) return 0.0f;
        const float d = densities_[address(p)];
        return std::isfinite(d) ? d : 0.0f;
    }
    uint8_t materialAt(glm::ivec3 p) const { return inside(p) ? materials_[address(p)] : kMaterialNone; }
    glm::vec3 gradient(glm::ivec3 p) const {
        return 0.5f * glm::vec3(at(p + glm::ivec3(1, 0, 0)) - at(p - glm::ivec3(1, 0, 0)),
                                at(p + glm::ivec3(0, 1, 0)) - at(p - glm::ivec3(0, 1, 0)),
                                at(p + glm::ivec3(0, 0, 1)) - at(p - glm::ivec3(0, 0, 1)));
    }

    // The samples p + [low, high] read as offsets from p's address, without bounds checks: most
    // vertices and cells lie inside one chunk of the grid with their neighbours.
    class Window {
    public:
        Window(const SampleReader& reader, glm::ivec3 p)
            : densities_(reader.densities_), materials_(reader.materials_), p_(p), address_(ptrdiff_t(reader.address(p))),
              stride_(ptrdiff_t(reader.layout_.chunkSize)) {}
        float at(glm::ivec3 q) const {
            const float d = densities_[offset(q)];
            return std::isfinite(d) ? d : 0.0f;
        }
        uint8_t materialAt(glm::ivec3 q) const { return materials_[offset(q)]; }
        glm::vec3 gradient(glm::ivec3 p) const {
            return 0.5f * glm::vec3(at(p + glm::ivec3(1, 0, 0)) - at(p - glm::ivec3(1, 0, 0)),
                                    at(p + glm::ivec3(0, 1, 0)) - at(p - glm::ivec3(0, 1, 0)),
                                    at(p + glm::ivec3(0, 0, 1)) - at(p - glm::ivec3(0, 0, 1)));
        }

    private:
        ptrdiff_t offset(glm::ivec3 q) const {
            const glm::ivec3 d = q - p_;
            return address_ + d.x + stride_ * (d.y + stride_ * d.z);
        }
        const float* densities_;
        const uint8_t* materials_;
        glm::ivec3 p_;
        ptrdiff_t address_, stride_;
    };
    // Whether p + [low, high] lies inside the grid and inside p's chunk (then Window reads it).
    bool windowFits(glm::ivec3 p, glm::ivec3 low, glm::ivec3 high) const {
        const glm::ivec3 in = (layout_.gridOrigin + p) & (layout_.chunkSize - 1);
        return glm::all(glm::greaterThanEqual(p + low, glm::ivec3(0))) && glm::all(glm::lessThan(p + high, layout_.gridSize)) &&
               glm::all(glm::greaterThanEqual(in + low, glm::ivec3(0))) && glm::all(glm::lessThan(in + high, glm::ivec3(layout_.chunkSize)));
    }

private:
    bool inside(glm::ivec3 p) const {
        return unsigned(p.x) < unsigned(layout_.gridSize.x) && unsigned(p.y) < unsigned(layout_.gridSize.y) &&
               unsigned(p.z) < unsigned(layout_.gridSize.z);
    }
    // ChunkLayout::address, inline for the vertex loop.
    size_t address(glm::ivec3 local) const {
        const glm::ivec3 world = layout_.gridOrigin + local;
        const glm::ivec3 entry = (world >> layout_.chunkShift) - layout_.chunkBase;
        const glm::ivec3 in = world & (layout_.chunkSize - 1);
        const size_t slot = size_t(entry.x) + size_t(layout_.chunkCount.x) * (size_t(entry.y) + size_t(layout_.chunkCount.y) * size_t(entry.z));
        const size_t c = size_t(layout_.chunkSize);
        return (slot << (3 * layout_.chunkShift)) + size_t(in.x) + c * (size_t(in.y) + c * size_t(in.z));
    }

    const ChunkLayout& layout_;
    const float* densities_;
    const uint8_t* materials_;
};

// The low `bits` bits of word `w` of a row of bits.
uint64_t rowMask(size_t w, int bits) {
    const int first = int(w) * 64;
    if (bits >= first + 64) return ~uint64_t(0);
    if (bits <= first) return 0;
    return (uint64_t(1) << (bits - first)) - 1;
}

// Bit x of the result is bit x + 1 of the row: the sample one step along +x.
uint64_t nextBits(const uint64_t* row, size_t w) { return (row[w] >> 1) | (row[w + 1] << 63); }

// A box of cells meshed from the sign bits of its samples: the cells the surface crosses are
// found 64 at a time (the corners' bits ORed and ANDed over the four sample rows a cell row reads),
// and only they, and the crossed edges, read densities. A count pass sizes every row's vertices
// and triangles, a prefix sum places them, and an emit pass writes them in place, so vertices come
// out in global edge order and triangles in global cell order, as mergeChunks orders the chunks'
// shares: the same mesh, bit for bit.
class SparseExtraction {
public:
    SparseExtraction(const ChunkedGrid& grid, const CellRange& cells, float iso, float margin, bool skip)
        : grid_(grid), reader_(grid), cells_(cells), iso_(iso), margin_(margin), skip_(skip),
          signs_(mesh_bits::classifySamples(grid, iso, cells.begin, cells.end - cells.begin + 1, skip ? grid.tileRanges() : nullptr)),
          extent_(signs_.extent), table_(caseTable()) {
        for (int e = 0; e < 12; ++e) {
            const glm::ivec3 o = cornerOffset(edgeCorners(e)[0]);
            edgeRefs_[e] = {o.x, o.y, o.z, edgeAxis(e)};
        }
    }

    Mesh run(MeshStats* stats) {
        const size_t rows = size_t(extent_.y) * size_t(extent_.z);
        rowVertices_.assign(rows + 1, 0);
        rowTriangles_.assign(rows + 1, 0);
        prepareCounters();
        forEachChunk(size_t(extent_.z), [&](size_t z) {
            countSlice(int(z));
            return true;
        });
        // Exclusive prefix sums: the first vertex and triangle of every row.
        uint64_t vertices = 0, triangles = 0;
        for (size_t r = 0; r <= rows; ++r) {
            const uint64_t v = rowVertices_[r], t = rowTriangles_[r];
            rowVertices_[r] = vertices;
            rowTriangles_[r] = triangles;
            vertices += v;
            triangles += t;
        }
        VOXC_ASSERT(vertices <= UINT32_MAX);
        // Sizing the arrays writes (and first touches) every page of the mesh: the two halves of
        // its bytes on two workers.
        Mesh mesh;
        forEachChunk(2, [&](size_t half) {
            if (half == 0) {
                resizeOnHugePages(mesh.triangles, triangles * 3);
                resizeOnHugePages(mesh.triangleMaterials, triangles);
            } else {
                resizeOnHugePages(mesh.positions, vertices);
                resizeOnHugePages(mesh.normals, vertices);
                resizeOnHugePages(mesh.vertexMaterials, vertices);
            }
            return true;
        });
        // Slabs of slices, a few per thread so that a slab near the surface does not hold the others up.
        const size_t slabs = std::min<size_t>(size_t(extent_.z), 4 * std::max(1u, std::thread::hardware_concurrency()));
        forEachChunk(slabs, [&](size_t s) {
            emitSlab(int(size_t(extent_.z) * s / slabs), int(size_t(extent_.z) * (s + 1) / slabs), mesh);
            return true;
        });
        if (stats) fillStats(*stats);
        return mesh;
    }

private:
    struct EdgeRef {
        int dx, dy, dz, axis;
    };
    struct RowEdges {
        uint64_t x, y, z;
    };

    size_t rowIndex(int y, int z) const { return size_t(z) * size_t(extent_.y) + size_t(y); }
    size_t usedWords() const { return signs_.words - 1; }

    // Crossed edges whose lower sample is in row (y, z), by the axis they run along. An edge
    // belongs to a cell of the box when its lower sample is in the box and it ends in the box.
    RowEdges rowEdges(int y, int z, size_t w) const {
        const uint64_t* s = signs_.row(y, z);
        RowEdges e{(s[w] ^ nextBits(s, w)) & rowMask(w, extent_.x - 1), 0, 0};
        if (y + 1 < extent_.y) e.y = (s[w] ^ signs_.row(y + 1, z)[w]) & rowMask(w, extent_.x);
        if (z + 1 < extent_.z) e.z = (s[w] ^ signs_.row(y, z + 1)[w]) & rowMask(w, extent_.x);
        return e;
    }

    // The four sample rows of cell row (y, z) and their bits one step along x: corner c of the
    // cell at bit i is bit i of corners[c].
    struct CellRowWord {
        uint64_t corners[8];
        uint64_t crossed;
    };
    CellRowWord cellRowWord(int y, int z, size_t w) const {
        CellRowWord c;
        const uint64_t* rows[4] = {signs_.row(y, z), signs_.row(y + 1, z), signs_.row(y, z + 1), signs_.row(y + 1, z + 1)};
        uint64_t any = 0, all = ~uint64_t(0);
        for (int r = 0; r < 4; ++r) {
            c.corners[2 * r] = rows[r][w];
            c.corners[2 * r + 1] = nextBits(rows[r], w);
            any |= c.corners[2 * r] | c.corners[2 * r + 1];
            all &= c.corners[2 * r] & c.corners[2 * r + 1];
        }
        const uint64_t cellsInRow = rowMask(w, extent_.x - 1);
        c.crossed = skip_ ? any & ~all & cellsInRow : cellsInRow;
        return c;
    }
    static unsigned caseAt(const CellRowWord& c, int bit) {
        unsigned solid = 0;
        for (int k = 0; k < 8; ++k) solid |= unsigned((c.corners[k] >> bit) & 1u) << k;
        return solid;
    }

    // World-aligned 8^3 tiles and the layout's chunks over the box's cells, for the counters.
    void prepareCounters() {
        const ChunkLayout& layout = grid_.layout();
        const glm::ivec3 firstCell = layout.gridOrigin + cells_.begin, lastCell = layout.gridOrigin + cells_.end - 1;
        tileFirst_ = firstCell >> 3;
        tileCount_ = (lastCell >> 3) - tileFirst_ + 1;
        chunkFirst_ = firstCell >> layout.chunkShift;
        chunkCount_ = (lastCell >> layout.chunkShift) - chunkFirst_ + 1;
        tileHit_ = std::vector<std::atomic<uint8_t>>(size_t(tileCount_.x) * tileCount_.y * tileCount_.z);
        chunkHit_ = std::vector<std::atomic<uint8_t>>(size_t(chunkCount_.x) * chunkCount_.y * chunkCount_.z);
    }
    // Written only when not yet set, so that the two threads do not fight over the cache line.
    static void markHit(std::atomic<uint8_t>& hit) {
        if (!hit.load(std::memory_order_relaxed)) hit.store(1, std::memory_order_relaxed);
    }
    static size_t flat(glm::ivec3 p, glm::ivec3 count) { return size_t(p.x) + size_t(count.x) * (size_t(p.y) + size_t(count.y) * size_t(p.z)); }

    void countSlice(int z) {
        const glm::ivec3 origin = grid_.layout().gridOrigin + signs_.first;
        const int shift = grid_.layout().chunkShift;
        size_t visited = 0;
        for (int y = 0; y < extent_.y; ++y) {
            uint64_t vertices = 0, triangles = 0;
            for (size_t w = 0; w < usedWords(); ++w) {
                const RowEdges e = rowEdges(y, z, w);
                // Most words cross nothing (std::popcount may be a library call on a baseline x86-64 build).
                if ((e.x | e.y | e.z) != 0) vertices += uint64_t(std::popcount(e.x) + std::popcount(e.y) + std::popcount(e.z));
                if (y + 1 >= extent_.y || z + 1 >= extent_.z) continue;
                const CellRowWord c = cellRowWord(y, z, w);
                for (uint64_t bits = c.crossed; bits != 0; bits &= bits - 1) {
                    const int bit = std::countr_zero(bits);
                    ++visited;
                    const uint8_t count = table_[caseAt(c, bit)].triangleCount;
                    if (count == 0) continue;
                    triangles += count;
                    const glm::ivec3 world = origin + glm::ivec3(int(w) * 64 + bit, y, z);
                    markHit(tileHit_[flat((world >> 3) - tileFirst_, tileCount_)]);
                    markHit(chunkHit_[flat((world >> shift) - chunkFirst_, chunkCount_)]);
                }
            }
            rowVertices_[rowIndex(y, z)] = vertices;
            rowTriangles_[rowIndex(y, z)] = triangles;
        }
        cellsVisited_ += visited;
    }

    // Slices [begin, end) of vertices and of cells; the slice after the last is read for the
    // indices of its vertices (the next slab writes them).
    void emitSlab(int begin, int end, Mesh& mesh) {
        const size_t sliceSize = size_t(extent_.x) * size_t(extent_.y) * 3;
        // Vertex index of edge (x, y, axis) of the slices z (slot z & 1); entries are written for
        // crossed edges only, and only those are read.
        std::unique_ptr<uint32_t[]> indices(new uint32_t[2 * sliceSize]);
        adviseHugePages(indices.get(), 2 * sliceSize * sizeof(uint32_t));
        for (int z = begin; z <= end && z < extent_.z; ++z) {
            indexSlice(z, indices.get() + size_t(z & 1) * sliceSize, z < end ? &mesh : nullptr);
            if (z > begin && z - 1 < extent_.z - 1) emitCells(z - 1, indices.get(), sliceSize, mesh);
        }
    }

    void indexSlice(int z, uint32_t* index, Mesh* mesh) const {
        const glm::ivec3 origin = grid_.layout().gridOrigin;
        for (int y = 0; y < extent_.y; ++y) {
            uint32_t next = uint32_t(rowVertices_[rowIndex(y, z)]);
            for (size_t w = 0; w < usedWords(); ++w) {
                const RowEdges e = rowEdges(y, z, w);
                for (uint64_t bits = e.x | e.y | e.z; bits != 0; bits &= bits - 1) {
                    const int bit = std::countr_zero(bits), x = int(w) * 64 + bit;
                    const uint64_t axes[3] = {e.x, e.y, e.z};
                    for (int axis = 0; axis < 3; ++axis) {
                        if (!((axes[axis] >> bit) & 1u)) continue;
                        index[(size_t(y) * size_t(extent_.x) + size_t(x)) * 3 + size_t(axis)] = next;
                        if (mesh) {
                            const glm::ivec3 lower = signs_.first + glm::ivec3(x, y, z);
                            const EdgeVertex v =
                                reader_.windowFits(lower, glm::ivec3(-1), glm::ivec3(1) + axisStep(axis))
                                    ? edgeVertex(SampleReader::Window(reader_, lower), lower, axis, iso_, margin_, origin)
                                    : edgeVertex(reader_, lower, axis, iso_, margin_, origin);
                            mesh->positions[next] = v.position;
                            mesh->normals[next] = v.normal;
                            mesh->vertexMaterials[next] = v.material;
                        }
                        ++next;
                    }
                }
            }
        }
    }

    void emitCells(int z, const uint32_t* indices, size_t sliceSize, Mesh& mesh) const {
        for (int y = 0; y + 1 < extent_.y; ++y) {
            size_t triangle = size_t(rowTriangles_[rowIndex(y, z)]);
            for (size_t w = 0; w < usedWords(); ++w) {
                const CellRowWord c = cellRowWord(y, z, w);
                for (uint64_t bits = c.crossed; bits != 0; bits &= bits - 1) {
                    const int bit = std::countr_zero(bits), x = int(w) * 64 + bit;
                    const unsigned solid = caseAt(c, bit);
                    const CellCase& cellCase = table_[solid];
                    if (cellCase.triangleCount == 0) continue;
                    const glm::ivec3 cell = signs_.first + glm::ivec3(x, y, z);
                    const uint8_t material = reader_.windowFits(cell, glm::ivec3(0), glm::ivec3(1))
                                                 ? majorityMaterial(SampleReader::Window(reader_, cell), cell, solid)
                                                 : majorityMaterial(reader_, cell, solid);
                    for (int t = 0; t < cellCase.triangleCount; ++t, ++triangle) {
                        for (int k = 0; k < 3; ++k) {
                            const EdgeRef& r = edgeRefs_[cellCase.edges[size_t(t * 3 + k)]];
                            const uint32_t* slice = indices + size_t((z + r.dz) & 1) * sliceSize;
                            mesh.triangles[triangle * 3 + size_t(k)] =
                                slice[(size_t(y + r.dy) * size_t(extent_.x) + size_t(x + r.dx)) * 3 + size_t(r.axis)];
                        }
                        mesh.triangleMaterials[triangle] = material;
                    }
                }
            }
        }
    }

    void fillStats(MeshStats& stats) const {
        const ChunkLayout& layout = grid_.layout();
        stats.chunks = cellChunks(layout).size();
        size_t hit = 0;
        for (const auto& h : chunkHit_) hit += h.load(std::memory_order_relaxed);
        // Without skipping only the chunks outside the box go unvisited.
        stats.skippedChunks = stats.chunks - (skip_ ? hit : chunkHit_.size());
        stats.tiles = tileHit_.size();
        stats.activeTiles = 0;
        for (const auto& h : tileHit_) stats.activeTiles += h.load(std::memory_order_relaxed);
        stats.cellsVisited = cellsVisited_.load();
        stats.samplesRead = signs_.samplesRead;
        stats.normalsMs = 0.0; // meshMarchingCubesCells adds the orientation's time
    }

    const ChunkedGrid& grid_;
    const SampleReader reader_;
    const CellRange cells_;
    const float iso_, margin_;
    const bool skip_;
    const mesh_bits::SignBits signs_;
    const glm::ivec3 extent_;
    const std::array<CellCase, 256>& table_;
    EdgeRef edgeRefs_[12];
    std::vector<uint64_t> rowVertices_, rowTriangles_;
    glm::ivec3 tileFirst_{0}, tileCount_{0}, chunkFirst_{0}, chunkCount_{0};
    std::vector<std::atomic<uint8_t>> tileHit_, chunkHit_;
    std::atomic<size_t> cellsVisited_{0};
};

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

const char* hostMeshSimd() { return mesh_bits::classificationPath(); }

Mesh meshMarchingCubesCells(const ChunkedGrid& grid, const CellBox& cells, float margin, const MeshOptions& options,
                            MeshStats* stats) {
    // The box's cells that are cells of the grid (-1 to its size - 1).
    const surface_nets::CellRange share{glm::max(cells.begin, glm::ivec3(-1)), glm::min(cells.end, grid.layout().gridSize)};
    if (share.empty()) {
        if (stats) *stats = MeshStats{cellChunks(grid.layout()).size(), cellChunks(grid.layout()).size()};
        return {};
    }
    Mesh mesh = marching_cubes::SparseExtraction(grid, share, options.iso, margin, options.skipUniformChunks).run(stats);
    // A vertex's normal follows the triangles around its edge (orientNormalsToFaces), some of
    // them in the cells just outside the box: they are meshed too, and the box's vertices take
    // their normals from that larger mesh, so a tile's vertices carry the whole world's bits.
    const surface_nets::CellRange around{glm::max(share.begin - 1, glm::ivec3(-1)), glm::min(share.end + 1, grid.layout().gridSize)};
    auto orient = [stats](Mesh& m) {
        const auto start = std::chrono::steady_clock::now();
        orientNormalsToFaces(m);
        if (stats) stats->normalsMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    };
    if (around.begin == share.begin && around.end == share.end) {
        orient(mesh);
        return mesh;
    }
    Mesh larger = marching_cubes::SparseExtraction(grid, around, options.iso, margin, options.skipUniformChunks).run(nullptr);
    orient(larger);
    // Both meshes list their vertices by global edge, the box's a subset of the larger's, and
    // no two edges share a position (the crossing margin), so one walk pairs them; the larger's
    // copies made for normals follow its edge vertices.
    const size_t largerEdges = larger.positions.size() - larger.normalSplits.size();
    std::vector<uint32_t> inLarger(mesh.positions.size());
    size_t at = 0;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        while (at < largerEdges && std::memcmp(&larger.positions[at], &mesh.positions[v], sizeof(glm::vec3)) != 0) ++at;
        VOXC_ASSERT(at < largerEdges);
        inLarger[v] = uint32_t(at);
        mesh.normals[v] = larger.normals[at];
    }
    // Triangles are in global cell order in both, the box's a subsequence of the larger's; each
    // takes the larger's corners, a copy there becoming a copy here.
    auto point = [&](uint32_t v) { return v >= largerEdges ? larger.normalSplits[v - largerEdges] : v; };
    std::vector<uint32_t> copyHere(larger.normalSplits.size(), UINT32_MAX);
    size_t u = 0;
    for (size_t t = 0; t < mesh.triangles.size() / 3; ++t) {
        auto same = [&] {
            for (size_t k = 0; k < 3; ++k)
                if (point(larger.triangles[u * 3 + k]) != inLarger[mesh.triangles[t * 3 + k]]) return false;
            return true;
        };
        while (u < larger.triangles.size() / 3 && !same()) ++u;
        VOXC_ASSERT(u < larger.triangles.size() / 3);
        for (size_t k = 0; k < 3; ++k) {
            const uint32_t corner = larger.triangles[u * 3 + k];
            if (corner < largerEdges) continue;
            uint32_t& copy = copyHere[corner - largerEdges];
            if (copy == UINT32_MAX) {
                const uint32_t original = mesh.triangles[t * 3 + k];
                copy = uint32_t(mesh.positions.size());
                mesh.positions.push_back(mesh.positions[original]);
                mesh.normals.push_back(larger.normals[corner]);
                mesh.vertexMaterials.push_back(mesh.vertexMaterials[original]);
                mesh.normalSplits.push_back(original);
            }
            mesh.triangles[t * 3 + k] = copy;
        }
        ++u;
    }
    return mesh;
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
    orientNormalsToFaces(mesh);
    return mesh;
}

} // namespace voxc
