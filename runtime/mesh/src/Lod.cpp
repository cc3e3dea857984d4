// Decimated levels, LOD layouts and the LOD mesher (voxc/mesh/Lod.h).
#include "voxc/mesh/Lod.h"

#include "ChunkWorkers.h"
#include "voxc/core/Errors.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/mesh/TransitionCells.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <unordered_map>

namespace voxc {
namespace {

int floorDiv(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
int ceilDiv(int a, int b) { return -floorDiv(-a, b); }
glm::ivec3 floorDiv(glm::ivec3 a, int b) { return {floorDiv(a.x, b), floorDiv(a.y, b), floorDiv(a.z, b)}; }
glm::ivec3 ceilDiv(glm::ivec3 a, int b) { return {ceilDiv(a.x, b), ceilDiv(a.y, b), ceilDiv(a.z, b)}; }

bool inside(glm::ivec3 p, glm::ivec3 size) {
    return glm::all(glm::greaterThanEqual(p, glm::ivec3(0))) && glm::all(glm::lessThan(p, size));
}

glm::ivec3 axisStep(int axis, int length = 1) {
    glm::ivec3 step(0);
    step[axis] = length;
    return step;
}

} // namespace

LodPyramid::LodPyramid(const ChunkedGrid& lod0, int maxLevel) : lod0_(&lod0) {
    VOXC_ASSERT(maxLevel >= 0 && maxLevel <= kMaxLodLevel);
    const ChunkLayout& base = lod0.layout();
    for (int k = 1; k <= maxLevel; ++k) {
        const int step = 1 << k;
        const glm::ivec3 first = ceilDiv(base.gridOrigin, step);
        const glm::ivec3 size = floorDiv(base.gridOrigin + base.gridSize - 1, step) - first + 1;
        if (glm::any(glm::lessThanEqual(size, glm::ivec3(0)))) {
            levels_.emplace_back(std::nullopt);
            continue;
        }
        levels_.emplace_back(ChunkedGrid(ChunkLayout::make(first, size, std::max(base.chunkSize >> k, 1))));
    }
    refresh(glm::ivec3(0), base.gridSize - 1);
}

void LodPyramid::refresh(glm::ivec3 first, glm::ivec3 last) {
    const ChunkLayout& base = lod0_->layout();
    first = glm::max(first, glm::ivec3(0));
    last = glm::min(last, base.gridSize - 1);
    for (int k = 1; k <= maxLevel(); ++k) {
        std::optional<ChunkedGrid>& level = levels_[size_t(k - 1)];
        if (!level) continue;
        const int step = 1 << k;
        const glm::ivec3 origin = level->layout().gridOrigin;
        // The level's lattice points inside the world box of the edited voxels.
        const glm::ivec3 from = ceilDiv(base.gridOrigin + first, step) - origin;
        const glm::ivec3 to = floorDiv(base.gridOrigin + last, step) - origin;
        for (int z = from.z; z <= to.z; ++z)
            for (int y = from.y; y <= to.y; ++y)
                for (int x = from.x; x <= to.x; ++x) {
                    const glm::ivec3 local(x, y, z);
                    const glm::ivec3 source = (origin + local) * step - base.gridOrigin;
                    level->at(local) = lod0_->at(source);
                    level->materialAt(local) = lod0_->materialAt(source);
                }
    }
}

float LodPyramid::at(int level, glm::ivec3 lattice) const {
    const ChunkedGrid* grid = level == 0 ? lod0_ : levels_[size_t(level - 1)] ? &*levels_[size_t(level - 1)] : nullptr;
    if (!grid) return 0.0f;
    const glm::ivec3 local = lattice - grid->layout().gridOrigin;
    if (!inside(local, grid->layout().gridSize)) return 0.0f;
    const float d = grid->at(local);
    return std::isfinite(d) ? d : 0.0f;
}

uint8_t LodPyramid::materialAt(int level, glm::ivec3 lattice) const {
    const ChunkedGrid* grid = level == 0 ? lod0_ : levels_[size_t(level - 1)] ? &*levels_[size_t(level - 1)] : nullptr;
    if (!grid) return kMaterialNone;
    const glm::ivec3 local = lattice - grid->layout().gridOrigin;
    return inside(local, grid->layout().gridSize) ? grid->materialAt(local) : kMaterialNone;
}

// --- Layouts ---------------------------------------------------------------------------------

LodLayout LodLayout::uniform(const ChunkLayout& grid, int level) {
    const std::vector<glm::ivec3> chunks = cellChunks(grid);
    LodLayout layout;
    layout.firstChunk = chunks.front();
    layout.chunkCount = chunks.back() - chunks.front() + 1;
    layout.chunkSize = grid.chunkSize;
    layout.levels.assign(chunks.size(), uint8_t(level));
    return layout;
}

LodLayout LodLayout::aroundPoint(const ChunkLayout& grid, glm::vec3 point, int maxLevel) {
    LodLayout layout = uniform(grid, 0);
    for (const glm::ivec3& chunk : cellChunks(grid)) {
        const glm::vec3 lo(chunk * layout.chunkSize), hi = lo + float(layout.chunkSize);
        const float distance = glm::length(glm::max(glm::max(lo - point, point - hi), glm::vec3(0.0f)));
        const int level = int(std::floor(std::log2(1.0f + distance / float(layout.chunkSize))));
        layout.setLevel(chunk, std::min(level, maxLevel));
    }
    balanceLod(layout);
    return layout;
}

bool LodLayout::contains(glm::ivec3 chunk) const { return inside(chunk - firstChunk, chunkCount); }

size_t LodLayout::index(glm::ivec3 chunk) const {
    VOXC_ASSERT(contains(chunk));
    const glm::ivec3 q = chunk - firstChunk;
    return size_t(q.x) + size_t(chunkCount.x) * (size_t(q.y) + size_t(chunkCount.y) * size_t(q.z));
}

int LodLayout::maxLevel() const { return levels.empty() ? 0 : *std::max_element(levels.begin(), levels.end()); }

namespace {

template <class Visit> void forEachChunkOf(const LodLayout& layout, Visit&& visit) {
    for (int z = 0; z < layout.chunkCount.z; ++z)
        for (int y = 0; y < layout.chunkCount.y; ++y)
            for (int x = 0; x < layout.chunkCount.x; ++x) visit(layout.firstChunk + glm::ivec3(x, y, z));
}

// The finest level among the chunks touching `chunk` (itself excluded), or -1 without any.
int finestTouching(const LodLayout& layout, glm::ivec3 chunk) {
    int finest = -1;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const glm::ivec3 n = chunk + glm::ivec3(dx, dy, dz);
                if ((dx | dy | dz) == 0 || !layout.contains(n)) continue;
                if (finest < 0 || layout.levelAt(n) < finest) finest = layout.levelAt(n);
            }
    return finest;
}

} // namespace

void balanceLod(LodLayout& layout) {
    for (bool changed = true; changed;) {
        changed = false;
        forEachChunkOf(layout, [&](glm::ivec3 chunk) {
            const int finest = finestTouching(layout, chunk);
            if (finest >= 0 && layout.levelAt(chunk) > finest + 1) {
                layout.setLevel(chunk, finest + 1);
                changed = true;
            }
        });
    }
}

void checkLodLayout(const LodLayout& layout) {
    if ((layout.chunkSize >> layout.maxLevel()) == 0)
        throw UserError(fmt::format("LOD level {} has cells {} voxels wide, wider than the {}-voxel chunks", layout.maxLevel(),
                                    1 << layout.maxLevel(), layout.chunkSize));
    forEachChunkOf(layout, [&](glm::ivec3 chunk) {
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const glm::ivec3 n = chunk + glm::ivec3(dx, dy, dz);
                    if (!layout.contains(n) || layout.levelAt(chunk) < layout.levelAt(n) + 2) continue;
                    throw UserError(fmt::format(
                        "LOD layout: chunk ({},{},{}) at level {} touches chunk ({},{},{}) at level {}; touching chunks may "
                        "differ by one level at most (2:1)",
                        chunk.x, chunk.y, chunk.z, layout.levelAt(chunk), n.x, n.y, n.z, layout.levelAt(n)));
                }
    });
}

// --- Meshing ---------------------------------------------------------------------------------

namespace {

using marching_cubes::CellTriangle;
using marching_cubes::ChunkMesh;
using marching_cubes::EdgeVertex;
namespace tc = transition_cells;

// Keys of lattice points, edges and cells, global and ordered like the regular mesher's (z, y, x
// of the lower corner, then axis, then level), so a level-0 layout orders its mesh the same way.
// A fanned loop's centre vertex is keyed by its cell and loop.
struct KeySpace {
    glm::ivec3 low;  // the lowest world point keyed: every cell corner is at least this
    glm::ivec3 span; // points per axis
    int levels;

    uint64_t point(glm::ivec3 world) const {
        const glm::ivec3 q = world - low;
        return uint64_t(q.x) + uint64_t(span.x) * (uint64_t(q.y) + uint64_t(span.y) * uint64_t(q.z));
    }
    // Slots 0-2 of a point are its edges' axes, the rest the centres of its cell's fanned loops.
    static constexpr uint64_t kSlots = 16;
    uint64_t edge(glm::ivec3 lower, int axis, int level) const {
        return (point(lower) * kSlots + uint64_t(axis)) * uint64_t(levels) + uint64_t(level);
    }
    uint64_t loopCentre(glm::ivec3 cell, int loop, int level) const {
        VOXC_ASSERT(loop >= 0 && uint64_t(loop) < kSlots - 3);
        return (point(cell) * kSlots + 3 + uint64_t(loop)) * uint64_t(levels) + uint64_t(level);
    }
};

// One chunk's samples on its block lattice (the chunk's step, or half of it next to a finer
// chunk), from one step below its first cell to one above its last cell's far corner (for the
// central differences), read from the pyramid.
class LodSamples {
public:
    LodSamples(const LodPyramid& pyramid, int level, glm::ivec3 first, glm::ivec3 last) : step_(1 << level), first_(first) {
        extent_ = (last - first) / step_ + 1;
        values_.resize(size_t(extent_.x) * size_t(extent_.y) * size_t(extent_.z));
        materials_.resize(values_.size());
        size_t i = 0;
        for (int z = 0; z < extent_.z; ++z)
            for (int y = 0; y < extent_.y; ++y)
                for (int x = 0; x < extent_.x; ++x, ++i) {
                    const glm::ivec3 lattice = first / step_ + glm::ivec3(x, y, z);
                    values_[i] = pyramid.at(level, lattice);
                    materials_[i] = pyramid.materialAt(level, lattice);
                }
    }
    float at(glm::ivec3 world) const { return values_[index(world)]; }
    uint8_t materialAt(glm::ivec3 world) const { return materials_[index(world)]; }
    glm::vec3 gradient(glm::ivec3 p, int length) const {
        return 0.5f * glm::vec3(at(p + axisStep(0, length)) - at(p - axisStep(0, length)),
                                at(p + axisStep(1, length)) - at(p - axisStep(1, length)),
                                at(p + axisStep(2, length)) - at(p - axisStep(2, length)));
    }
    bool uniform(glm::ivec3 from, glm::ivec3 to, float iso) const {
        const bool first = at(from) > iso;
        for (int z = from.z; z <= to.z; z += step_)
            for (int y = from.y; y <= to.y; y += step_)
                for (int x = from.x; x <= to.x; x += step_)
                    if ((at({x, y, z}) > iso) != first) return false;
        return true;
    }

private:
    size_t index(glm::ivec3 world) const {
        const glm::ivec3 q = (world - first_) / step_;
        VOXC_ASSERT(inside(q, extent_) && q * step_ == world - first_);
        return size_t(q.x) + size_t(extent_.x) * (size_t(q.y) + size_t(extent_.y) * size_t(q.z));
    }

    int step_;
    glm::ivec3 first_, extent_;
    std::vector<float> values_;
    std::vector<uint8_t> materials_;
};

// The vertex on the level-`level` lattice edge from `lower` along `axis`: MarchingCubes.cpp's
// edgeVertex with the edge 2^level long.
//
// At a coarser level an edge that leaves the grid spans up to 2^level - 1 voxels of the air outside,
// so its crossing would put the world's wall up to that far beyond level 0's (which lies within half
// a voxel of the last voxel for densities in [0, 1]): the vertex is clamped, along its edge, to the
// world's box [origin - 0.5, origin + size - 0.5]. The edge's inside sample lies within that box and
// its outside one beyond it, so the vertex stays inside its edge.
EdgeVertex edgeVertex(const LodSamples& samples, const KeySpace& keys, const ChunkLayout& grid, glm::ivec3 lower, int axis,
                      int level, float iso, float margin) {
    const int length = 1 << level;
    const glm::ivec3 upper = lower + axisStep(axis, length);
    const float d0 = samples.at(lower), d1 = samples.at(upper);
    const float t = marching_cubes::crossing(d0, d1, iso, margin);
    glm::vec3 position(lower);
    position[axis] += t * float(length);
    if (level > 0)
        position[axis] = std::clamp(position[axis], float(grid.gridOrigin[axis]) - 0.5f,
                                    float(grid.gridOrigin[axis] + grid.gridSize[axis]) - 0.5f);
    const glm::vec3 gradient = (1.0f - t) * samples.gradient(lower, length) + t * samples.gradient(upper, length);
    const float norm = glm::length(gradient);
    glm::vec3 normal;
    if (norm > 0.0f && std::isfinite(norm)) {
        normal = -gradient / norm;
    } else {
        normal = glm::vec3(0.0f);
        normal[axis] = d0 > iso ? 1.0f : -1.0f;
    }
    return {keys.edge(lower, axis, level), position, normal, samples.materialAt(d0 > iso ? lower : upper)};
}

// The corner numbering of the regular table (MarchingCubes.h) as lattice points of a cell.
int cornerPoint(int corner) { return tc::pointAt(2 * marching_cubes::cornerOffset(corner)); }

// The most common material among the cell's solid samples (ascending point, which for a regular
// cell is the regular mesher's corner order); ties go to the lowest id.
template <class PointWorld>
uint8_t majorityMaterial(const LodSamples& samples, uint32_t points, uint32_t solid, PointWorld&& pointWorld) {
    int votes[256] = {};
    uint8_t best = kMaterialNone;
    for (int p = 0; p < tc::kPoints; ++p) {
        if (!((points & solid) >> p & 1u)) continue;
        const uint8_t m = samples.materialAt(pointWorld(p));
        ++votes[m];
        if (votes[m] > votes[best] || (votes[m] == votes[best] && m < best)) best = m;
    }
    return best;
}

struct ChunkPlan {
    glm::ivec3 chunk;
    int level;
    std::vector<std::pair<glm::ivec3, glm::ivec3>> finerBoxes; // closed world boxes of finer touching chunks
};

class ChunkExtractor {
public:
    ChunkExtractor(const LodPyramid& pyramid, const LodLayout& layout, const KeySpace& keys, float iso, float margin)
        : pyramid_(pyramid), layout_(layout), keys_(keys), iso_(iso), margin_(margin) {}

    ChunkPlan plan(glm::ivec3 chunk) const {
        ChunkPlan plan{chunk, layout_.levelAt(chunk), {}};
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const glm::ivec3 n = chunk + glm::ivec3(dx, dy, dz);
                    if (!layout_.contains(n) || layout_.levelAt(n) >= plan.level) continue;
                    plan.finerBoxes.push_back({n * layout_.chunkSize, (n + 1) * layout_.chunkSize});
                }
        return plan;
    }

    // The chunk's cells' minimum corners, first and last (world), on its level's lattice: those
    // whose box meets the grid or its first outside layer (as the regular mesher's cells do).
    std::pair<glm::ivec3, glm::ivec3> cellRange(const ChunkPlan& plan) const {
        const ChunkLayout& grid = pyramid_.lod0().layout();
        const int step = 1 << plan.level;
        const glm::ivec3 chunkFirst = plan.chunk * layout_.chunkSize;
        const glm::ivec3 lowest = floorDiv(grid.gridOrigin - 1, step) * step;
        const glm::ivec3 highest = grid.gridOrigin + grid.gridSize - 1;
        const glm::ivec3 first = glm::max(chunkFirst, lowest);
        const glm::ivec3 last = glm::min(chunkFirst + layout_.chunkSize - step, floorDiv(highest, step) * step);
        return {first, last};
    }

    // The world box of the samples the chunk reads (its cells' corners and, for the normals, one
    // step further); empty (first > last) when it has no cells.
    std::pair<glm::ivec3, glm::ivec3> readBox(const ChunkPlan& plan) const {
        const auto [first, last] = cellRange(plan);
        const int step = 1 << plan.level;
        if (glm::any(glm::lessThan(last, first))) return {first, last};
        return {first - step, last + 2 * step};
    }
    glm::ivec3 gridOrigin() const { return pyramid_.lod0().layout().gridOrigin; }

    // The chunk's cells that take samples of the finer level (for LodStats).
    size_t countTransitionCells(const ChunkPlan& plan) const {
        if (plan.finerBoxes.empty()) return 0;
        const auto [first, last] = cellRange(plan);
        const int step = 1 << plan.level;
        size_t count = 0;
        for (int z = first.z; z <= last.z; z += step)
            for (int y = first.y; y <= last.y; y += step)
                for (int x = first.x; x <= last.x; x += step) count += cellPoints(plan, {x, y, z}) != tc::kCornerPoints;
        return count;
    }

    // Returns false when the chunk is skipped: every sample its cells read is on one side of iso.
    bool extract(const ChunkPlan& plan, bool skipUniform, ChunkMesh& out) const {
        const auto [first, last] = cellRange(plan);
        if (glm::any(glm::lessThan(last, first))) return true;
        const int step = 1 << plan.level;
        const int blockLevel = plan.finerBoxes.empty() ? plan.level : plan.level - 1;
        const auto [readFirst, readLast] = readBox(plan);
        const LodSamples samples(pyramid_, blockLevel, readFirst, readLast);
        if (skipUniform && samples.uniform(first, last + step, iso_)) return false;

        const std::array<marching_cubes::CellCase, 256>& table = marching_cubes::caseTable();
        std::unordered_map<uint64_t, tc::CellTriangles> derived; // transition cases met in this chunk
        for (int z = first.z; z <= last.z; z += step)
            for (int y = first.y; y <= last.y; y += step)
                for (int x = first.x; x <= last.x; x += step) {
                    const glm::ivec3 cell(x, y, z);
                    const uint32_t points = cellPoints(plan, cell);
                    auto pointWorld = [&](int p) { return cell + tc::pointOffset(p) * step / 2; };
                    uint32_t solid = 0;
                    for (int p = 0; p < tc::kPoints; ++p)
                        if ((points >> p) & 1u && samples.at(pointWorld(p)) > iso_) solid |= 1u << p;
                    if (solid == 0 || solid == points) continue;

                    const uint64_t cellKey = keys_.point(cell);
                    const uint8_t material = majorityMaterial(samples, points, solid, pointWorld);
                    auto vertexOf = [&](glm::ivec3 lower, int axis, int level) {
                        const EdgeVertex v = edgeVertex(samples, keys_, pyramid_.lod0().layout(), lower, axis, level, iso_, margin_);
                        out.vertices.push_back(v);
                        return v;
                    };
                    auto emit = [&](const std::array<uint64_t, 3>& corners) { out.triangles.push_back({cellKey, corners, material}); };
                    if (points == tc::kCornerPoints) {
                        unsigned mask = 0;
                        for (int c = 0; c < 8; ++c)
                            if ((solid >> cornerPoint(c)) & 1u) mask |= 1u << c;
                        const marching_cubes::CellCase& cellCase = table[mask];
                        for (int t = 0; t < cellCase.triangleCount; ++t) {
                            std::array<uint64_t, 3> corners;
                            for (int k = 0; k < 3; ++k) {
                                const int e = cellCase.edges[size_t(t * 3 + k)];
                                corners[size_t(k)] = vertexOf(cell + marching_cubes::cornerOffset(marching_cubes::edgeCorners(e)[0]) * step,
                                                              marching_cubes::edgeAxis(e), plan.level)
                                                         .edge;
                            }
                            emit(corners);
                        }
                        continue;
                    }
                    const uint64_t caseKey = uint64_t(points) << tc::kPoints | solid;
                    auto found = derived.find(caseKey);
                    if (found == derived.end()) found = derived.emplace(caseKey, tc::deriveCell(points, solid)).first;
                    const tc::CellTriangles& cellCase = found->second;
                    auto subEdgeVertex = [&](const tc::SubEdge& e) {
                        return vertexOf(pointWorld(e.lower), e.axis, e.halfSteps == 2 ? plan.level : plan.level - 1);
                    };
                    // A fanned loop's centre: the mean of its vertices moved a quarter of the way to
                    // the cell's centre, strictly inside the cell (a loop can lie flat in a face, and
                    // its mean on a neighbour's edge), their normals averaged.
                    for (size_t loop = 0; loop < cellCase.centredLoops.size(); ++loop) {
                        glm::vec3 sum(0.0f), normal(0.0f);
                        for (const tc::SubEdge& e : cellCase.centredLoops[loop]) {
                            const EdgeVertex v = subEdgeVertex(e);
                            sum += v.position;
                            normal += v.normal;
                        }
                        const float length = glm::length(normal);
                        const glm::vec3 mean = sum / float(cellCase.centredLoops[loop].size());
                        const glm::vec3 cellCentre = glm::vec3(cell) + 0.5f * float(step);
                        out.vertices.push_back({keys_.loopCentre(cell, int(loop), plan.level), mean + 0.25f * (cellCentre - mean),
                                                length > 0.0f ? normal / length : glm::vec3(0.0f, 1.0f, 0.0f), material});
                    }
                    for (size_t i = 0; i < cellCase.corners.size(); i += 3) {
                        std::array<uint64_t, 3> corners;
                        for (size_t k = 0; k < 3; ++k) {
                            const tc::CellVertex& c = cellCase.corners[i + k];
                            corners[k] = c.loop >= 0 ? keys_.loopCentre(cell, c.loop, plan.level) : subEdgeVertex(c.edge).edge;
                        }
                        emit(corners);
                    }
                }
        // Each cell lists its vertices once per triangle; one copy per edge is enough for the merge.
        std::sort(out.vertices.begin(), out.vertices.end(), [](const EdgeVertex& a, const EdgeVertex& b) { return a.edge < b.edge; });
        out.vertices.erase(std::unique(out.vertices.begin(), out.vertices.end(),
                                       [](const EdgeVertex& a, const EdgeVertex& b) { return a.edge == b.edge; }),
                           out.vertices.end());
        return true;
    }

private:
    // The cell's samples: its corners, plus the midpoints of its edges and the centres of its faces
    // that lie in a finer touching chunk's closed box (the finer chunk's lattice runs through them).
    uint32_t cellPoints(const ChunkPlan& plan, glm::ivec3 cell) const {
        uint32_t points = tc::kCornerPoints;
        if (plan.finerBoxes.empty()) return points;
        const int half = 1 << (plan.level - 1);
        for (int p = 0; p < tc::kPoints; ++p) {
            const glm::ivec3 o = tc::pointOffset(p);
            const int halves = (o.x == 1) + (o.y == 1) + (o.z == 1);
            if (halves == 0 || halves == 3) continue;
            const glm::ivec3 world = cell + o * half;
            for (const auto& [lo, hi] : plan.finerBoxes)
                if (glm::all(glm::greaterThanEqual(world, lo)) && glm::all(glm::lessThanEqual(world, hi))) {
                    points |= 1u << p;
                    break;
                }
        }
        return points;
    }

    const LodPyramid& pyramid_;
    const LodLayout& layout_;
    const KeySpace& keys_;
    float iso_, margin_;
};

} // namespace

struct LodMesher::State {
    State(const LodPyramid& pyramid, const LodLayout& layout, const MeshOptions& options)
        : layout(layout), options(options), keys(keySpace(pyramid.lod0().layout(), layout)),
          extractor(pyramid, this->layout, keys, options.iso, marching_cubes::crossingMargin(pyramid.lod0().layout())) {}

    static KeySpace keySpace(const ChunkLayout& grid, const LodLayout& layout) {
        const int pad = 1 << layout.maxLevel();
        return {grid.gridOrigin - pad, grid.gridSize + 2 * pad + 1, layout.maxLevel() + 1};
    }

    // Extracts the chunks `which` (indices into plans), each into its own part.
    size_t extract(const std::vector<size_t>& which) {
        return forEachChunk(which.size(), [&](size_t i) {
            parts[which[i]] = ChunkMesh{};
            return extractor.extract(plans[which[i]], options.skipUniformChunks, parts[which[i]]);
        });
    }

    const LodLayout layout;
    const MeshOptions options;
    const KeySpace keys;
    const ChunkExtractor extractor;
    std::vector<ChunkPlan> plans;
    std::vector<ChunkMesh> parts;
    LodStats stats;
};

LodMesher::LodMesher(const LodPyramid& pyramid, const LodLayout& layout, const MeshOptions& options) {
    checkLodLayout(layout);
    const ChunkLayout& grid = pyramid.lod0().layout();
    const LodLayout expected = LodLayout::uniform(grid, 0);
    if (layout.firstChunk != expected.firstChunk || layout.chunkCount != expected.chunkCount || layout.chunkSize != grid.chunkSize)
        throw InternalError("meshLod: the layout does not cover the grid's chunks");
    if (layout.maxLevel() > pyramid.maxLevel()) throw InternalError("meshLod: the layout needs levels the pyramid lacks");

    state_ = std::make_unique<State>(pyramid, layout, options);
    State& s = *state_;
    std::vector<size_t> all;
    for (const glm::ivec3& chunk : cellChunks(grid)) {
        all.push_back(s.plans.size());
        s.plans.push_back(s.extractor.plan(chunk));
    }
    s.parts.resize(s.plans.size());
    s.stats.chunks = s.plans.size();
    s.stats.skippedChunks = s.extract(all);
    for (const ChunkPlan& plan : s.plans) {
        ++s.stats.chunksPerLevel[size_t(plan.level)];
        s.stats.transitionCells += s.extractor.countTransitionCells(plan);
        for (int axis = 0; axis < 3; ++axis)
            for (int side : {-1, 1}) {
                const glm::ivec3 n = plan.chunk + axisStep(axis, side);
                s.stats.transitionFaces += layout.contains(n) && layout.levelAt(n) < plan.level;
            }
    }
}

LodMesher::~LodMesher() = default;

std::vector<glm::ivec3> LodMesher::update(glm::ivec3 first, glm::ivec3 last) {
    State& s = *state_;
    const glm::ivec3 origin = s.extractor.gridOrigin();
    const glm::ivec3 editFirst = origin + first, editLast = origin + last;
    std::vector<size_t> reached;
    std::vector<glm::ivec3> chunks;
    for (size_t i = 0; i < s.plans.size(); ++i) {
        const auto [readFirst, readLast] = s.extractor.readBox(s.plans[i]);
        if (glm::any(glm::lessThan(readLast, editFirst)) || glm::any(glm::greaterThan(readFirst, editLast))) continue;
        reached.push_back(i);
        chunks.push_back(s.plans[i].chunk);
    }
    s.extract(reached);
    return chunks;
}

Mesh LodMesher::mesh() const& { return marching_cubes::mergeChunks(state_->parts); }
Mesh LodMesher::mesh() && { return marching_cubes::mergeChunks(std::move(state_->parts)); }

const LodStats& LodMesher::stats() const { return state_->stats; }

Mesh meshLod(const LodPyramid& pyramid, const LodLayout& layout, const MeshOptions& options, LodStats* stats) {
    LodMesher mesher(pyramid, layout, options);
    if (stats) *stats = mesher.stats();
    return std::move(mesher).mesh();
}

} // namespace voxc
