#include "CellExtraction.h"

#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace voxc::surface_nets {
namespace {

bool insideGrid(const ChunkedGrid& grid, glm::ivec3 p) {
    return glm::all(glm::greaterThanEqual(p, glm::ivec3(0))) && glm::all(glm::lessThan(p, grid.layout().gridSize));
}

// A density as the mesher reads it: one that is not finite counts as 0, as the pipeline stores it
// (docs/language.md, "Non-finite values"), so a grid from elsewhere holding NaN or infinities
// meshes like one voxc made; outside the grid is 0 too (air).
float meshDensity(const ChunkedGrid& grid, glm::ivec3 p) {
    if (!insideGrid(grid, p)) return 0.0f;
    const float d = grid.at(p);
    return std::isfinite(d) ? d : 0.0f;
}

// Densities and materials of a chunk's cells plus a one-sample margin on every side (the extra
// sample on the low side and the second one on the high side feed the central-difference gradients).
class SampleBlock {
public:
    SampleBlock(const ChunkedGrid& grid, glm::ivec3 first, glm::ivec3 extent) : first_(first), extent_(extent) {
        const size_t count = size_t(extent.x) * size_t(extent.y) * size_t(extent.z);
        values_.resize(count);
        materials_.resize(count);
        size_t i = 0;
        for (int z = 0; z < extent.z; ++z)
            for (int y = 0; y < extent.y; ++y)
                for (int x = 0; x < extent.x; ++x, ++i) {
                    const glm::ivec3 p = first + glm::ivec3(x, y, z);
                    const bool inside = insideGrid(grid, p);
                    values_[i] = meshDensity(grid, p);
                    materials_[i] = inside ? grid.materialAt(p) : kMaterialNone;
                }
    }

    float at(glm::ivec3 local) const { return values_[index(local)]; }
    uint8_t materialAt(glm::ivec3 local) const { return materials_[index(local)]; }

    glm::vec3 gradient(glm::ivec3 p) const {
        return 0.5f * glm::vec3(at(p + glm::ivec3(1, 0, 0)) - at(p - glm::ivec3(1, 0, 0)),
                                at(p + glm::ivec3(0, 1, 0)) - at(p - glm::ivec3(0, 1, 0)),
                                at(p + glm::ivec3(0, 0, 1)) - at(p - glm::ivec3(0, 0, 1)));
    }

private:
    size_t index(glm::ivec3 local) const {
        const glm::ivec3 q = local - first_;
        return size_t(q.x) + size_t(extent_.x) * (size_t(q.y) + size_t(extent_.y) * size_t(q.z));
    }

    glm::ivec3 first_, extent_;
    std::vector<float> values_;
    std::vector<uint8_t> materials_;
};

// Corner i of a cell is at offset (i&1, (i>>1)&1, (i>>2)&1).
glm::ivec3 cornerOffset(int i) { return {i & 1, (i >> 1) & 1, (i >> 2) & 1}; }

CellVertex makeVertex(const SampleBlock& block, glm::ivec3 cell, glm::ivec3 world, const float (&density)[8], unsigned solid, float iso) {
    glm::vec3 sum(0.0f);
    int crossings = 0;
    for (int bit : {1, 2, 4})
        for (int a = 0; a < 8; ++a) {
            const int b = a | bit;
            if ((a & bit) || ((solid >> a) & 1) == ((solid >> b) & 1)) continue;
            // In double: iso lies between the two densities, so t is in [0, 1] even where the
            // float differences of far-apart densities would overflow.
            const float t = float((double(iso) - density[a]) / (double(density[b]) - density[a]));
            const glm::vec3 pa(cornerOffset(a)), pb(cornerOffset(b));
            sum += pa + t * (pb - pa);
            ++crossings;
        }
    const glm::vec3 inCell = sum / float(crossings);

    // Trilinear blend of the corner gradients at the vertex; density rises into the solid,
    // so the outward normal is the negated gradient.
    glm::vec3 gradient(0.0f);
    for (int i = 0; i < 8; ++i) {
        const glm::ivec3 o = cornerOffset(i);
        const float w = (o.x ? inCell.x : 1.0f - inCell.x) * (o.y ? inCell.y : 1.0f - inCell.y) * (o.z ? inCell.z : 1.0f - inCell.z);
        gradient += w * block.gradient(cell + o);
    }
    // A gradient that vanishes, or overflows between huge densities, leaves the normal to the faces.
    const float length = glm::length(gradient);
    const glm::vec3 normal = length > 0.0f && std::isfinite(length) ? -gradient / length : glm::vec3(0.0f);
    return {0, glm::vec3(world) + inCell, normal, kMaterialNone};
}

// The most common material among the solid corners; ties go to the lowest id.
uint8_t majorityMaterial(const SampleBlock& block, glm::ivec3 cell, unsigned solid) {
    uint8_t materials[8];
    int count = 0;
    for (int i = 0; i < 8; ++i)
        if ((solid >> i) & 1) materials[count++] = block.materialAt(cell + cornerOffset(i));
    uint8_t best = kMaterialNone;
    int bestVotes = 0;
    for (int i = 0; i < count; ++i) {
        int votes = 0;
        for (int j = 0; j < count; ++j) votes += materials[j] == materials[i];
        if (votes > bestVotes || (votes == bestVotes && materials[i] < best)) {
            best = materials[i];
            bestVotes = votes;
        }
    }
    return best;
}

} // namespace

CellRange chunkCells(const ChunkLayout& layout, glm::ivec3 worldChunk) {
    const glm::ivec3 chunkFirst = worldChunk * layout.chunkSize - layout.gridOrigin; // grid-local
    return {glm::max(chunkFirst, glm::ivec3(-1)), glm::min(chunkFirst + layout.chunkSize, layout.gridSize)};
}

namespace {

// True when the grid's tile ranges show every sample of [first, last] (grid-local, inclusive; the
// outside of the grid reads 0) on one side of iso; false when they do not or the grid has none.
bool rangesShowUniform(const ChunkedGrid& grid, float iso, glm::ivec3 first, glm::ivec3 last) {
    const TileRanges* ranges = grid.tileRanges();
    if (!ranges) return false;
    const ChunkLayout& layout = grid.layout();
    const glm::ivec3 inFirst = glm::max(first, glm::ivec3(0)), inLast = glm::min(last, layout.gridSize - 1);
    if (glm::any(glm::greaterThan(inFirst, inLast))) return false; // wholly outside: left to the samples
    const bool outside = glm::any(glm::lessThan(first, inFirst)) || glm::any(glm::greaterThan(last, inLast));
    int side = outside ? (0.0f > iso ? 1 : 0) : -1; // 1 solid, 0 air, -1 not yet known
    const glm::ivec3 tileFirst = (layout.gridOrigin + inFirst) >> TileRanges::kShift;
    const glm::ivec3 tileLast = (layout.gridOrigin + inLast) >> TileRanges::kShift;
    for (int z = tileFirst.z; z <= tileLast.z; ++z)
        for (int y = tileFirst.y; y <= tileLast.y; ++y)
            for (int x = tileFirst.x; x <= tileLast.x; ++x) {
                const TileRanges::Range& range = ranges->at({x, y, z});
                const int tileSide = range.low > iso ? 1 : range.high <= iso ? 0 : -1;
                if (tileSide < 0 || (side >= 0 && tileSide != side)) return false;
                side = tileSide;
            }
    return true;
}

} // namespace

bool cellsAreUniform(const ChunkedGrid& grid, float iso, const CellRange& cells) {
    // The ranges, where the grid has them, answer most chunks without reading a voxel; they never
    // call a chunk uniform that is not, so the answer is the samples' answer.
    if (rangesShowUniform(grid, iso, cells.begin, cells.end)) return true;
    auto solidAt = [&](glm::ivec3 p) { return meshDensity(grid, p) > iso; }; // as SampleBlock reads it
    const bool first = solidAt(cells.begin);
    for (int z = cells.begin.z; z <= cells.end.z; ++z)
        for (int y = cells.begin.y; y <= cells.end.y; ++y)
            for (int x = cells.begin.x; x <= cells.end.x; ++x)
                if (solidAt({x, y, z}) != first) return false;
    return true;
}

namespace {

// Cells [lo, hi) of a chunk, read from its sample block.
void extractCells(const SampleBlock& block, const CellDomain& domain, glm::ivec3 gridOrigin, glm::ivec3 lo, glm::ivec3 hi, float iso,
                  ChunkSurface& surface) {
    for (int z = lo.z; z < hi.z; ++z)
        for (int y = lo.y; y < hi.y; ++y)
            for (int x = lo.x; x < hi.x; ++x) {
                const glm::ivec3 cell(x, y, z);
                float density[8];
                unsigned solid = 0;
                for (int i = 0; i < 8; ++i) {
                    density[i] = block.at(cell + cornerOffset(i));
                    if (density[i] > iso) solid |= 1u << i;
                }
                if (solid == 0 || solid == 0xffu) continue;
                CellVertex vertex = makeVertex(block, cell, gridOrigin + cell, density, solid, iso);
                vertex.cell = domain.key(cell);
                vertex.material = majorityMaterial(block, cell, solid);
                surface.vertices.push_back(vertex);

                // The three grid edges leaving this cell's minimum corner belong to this cell.
                for (int axis = 0; axis < 3; ++axis) {
                    const bool solidAtMin = solid & 1u;
                    if (solidAtMin == bool(solid & (1u << (1 << axis)))) continue;
                    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                    glm::ivec3 eu(0), ev(0);
                    eu[u] = 1;
                    ev[v] = 1;
                    // Edges on the grid's low faces lie wholly in the outside air (for iso >= 0);
                    // skipping them keeps every quad's four cells inside the cell domain.
                    if (cell[u] < 0 || cell[v] < 0) continue;
                    const glm::ivec3 solidVoxel = cell + (solidAtMin ? glm::ivec3(0) : cornerOffset(1 << axis));
                    EdgeQuad quad{domain.key(cell) * 3 + uint64_t(axis), {}, block.materialAt(solidVoxel)};
                    // Counter-clockwise around +axis; reversed when the solid lies on the + side.
                    const glm::ivec3 ring[4] = {cell - eu - ev, cell - ev, cell, cell - eu};
                    for (int k = 0; k < 4; ++k) quad.cells[k] = domain.key(ring[solidAtMin ? k : (4 - k) % 4]);
                    surface.quads.push_back(quad);
                }
            }
}

} // namespace

ChunkSurface extractChunk(const ChunkedGrid& grid, float iso, glm::ivec3 worldChunk) {
    const ChunkLayout& layout = grid.layout();
    const CellDomain domain{layout.gridSize};
    const CellRange cells = chunkCells(layout, worldChunk);
    const glm::ivec3 cellBegin = cells.begin, cellEnd = cells.end;
    ChunkSurface surface;
    if (cells.empty()) return surface;
    const SampleBlock block(grid, cellBegin - 1, cellEnd - cellBegin + 3);

    // The cells go by world-aligned 8^3 tile; with the grid's tile ranges a tile of cells whose
    // samples all lie on one side of iso has no crossed cell or edge and is passed over. The
    // merge orders vertices by cell and quads by edge, so the order within a chunk is free.
    const bool ranged = grid.tileRanges() != nullptr;
    constexpr int tileSide = 1 << TileRanges::kShift;
    const glm::ivec3 tileFirst = (layout.gridOrigin + cellBegin) >> TileRanges::kShift;
    const glm::ivec3 tileLast = (layout.gridOrigin + cellEnd - 1) >> TileRanges::kShift;
    for (int tz = tileFirst.z; tz <= tileLast.z; ++tz)
        for (int ty = tileFirst.y; ty <= tileLast.y; ++ty)
            for (int tx = tileFirst.x; tx <= tileLast.x; ++tx) {
                const glm::ivec3 tileCells = glm::ivec3(tx, ty, tz) * tileSide - layout.gridOrigin;
                const glm::ivec3 lo = glm::max(cellBegin, tileCells), hi = glm::min(cellEnd, tileCells + tileSide);
                // Cells [lo, hi) read the samples [lo, hi] (their corners).
                if (ranged && rangesShowUniform(grid, iso, lo, hi)) continue;
                extractCells(block, domain, layout.gridOrigin, lo, hi, iso, surface);
            }
    return surface;
}

} // namespace voxc::surface_nets
