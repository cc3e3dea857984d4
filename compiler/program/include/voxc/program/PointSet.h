#pragma once
// A table of points and segments that a field reads through a `FieldNode::Kind::PointSet` node:
// the node's value at position p is vec2(min(D_c, centreReach), min(D_s, segmentReach)), D_c the
// least scaled distance |p - c_i| * s_i over the centres (the carve scales by 1/radius, so each
// centre has its own size) and D_s the distance to the nearest segment. Capping the distances at the
// reaches makes the value independent of which points farther away are looked at, so every
// backend reads per-cell lists of the points whose reach meets the cell (world-aligned cubes of
// kPointSetCellSize voxels over the grid, whatever the chunk size) and still computes the same
// floats. Each list is sorted by a conservative lower bound of its points' distances to the cell,
// so a loop stops at the first point that cannot be nearer than the nearest so far.
// The L-system cave carve (docs/architecture.md, "Carving") builds one from a skeleton.
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <span>
#include <vector>

namespace voxc {

struct PointSetSegment {
    glm::vec3 from{0.0f};
    glm::vec3 delta{0.0f};            // to - from
    float inverseLengthSquared = 0.0f; // 1 / |delta|^2; 0 for a degenerate segment (its distance is to `from`)
};

// The edge of a list cell in voxels: small cells keep the lists (the loop per voxel) short.
constexpr int32_t kPointSetCellSize = 8;

// One entry of a cell's list: a centre or segment index and a lower bound of the squared distance
// (as the backends compute it in float) from any voxel of the cell to it.
struct PointListItem {
    uint32_t index = 0;
    float lowerBoundSquared = 0.0f;
};

// Per cell of a world-aligned grid of cubes (cellSize voxels, cell c holds world voxels
// c * cellSize .. c * cellSize + cellSize - 1), the centres and segments whose reach meets the
// cell, sorted by lower bound (then index): start[i] .. start[i + 1] index `items`, cells x
// fastest, then y, then z.
struct PointBins {
    glm::ivec3 firstCell{0}, cellCount{0};
    int32_t cellSize = 1;
    std::vector<uint32_t> centreStart, segmentStart; // cells + 1 entries
    std::vector<PointListItem> centreItems, segmentItems;

    uint64_t cells() const { return uint64_t(cellCount.x) * uint64_t(cellCount.y) * uint64_t(cellCount.z); }
};

struct PointSet {
    std::vector<glm::vec3> centres;
    std::vector<float> centreScales; // per centre, > 0: its distances count s_i times
    std::vector<PointSetSegment> segments;
    float centreReach = 0.0f;  // > 0, in scaled distance
    float segmentReach = 0.0f; // > 0
    // The field built from the set makes air within this of a segment (the carve's r_clear; every
    // voxel closer than it by 1e-4 is air); later stages that must keep those voxels air ask
    // pointSetClearance. 0: none.
    float clearance = 0.0f;
    PointBins bins;            // the interpreter's lists (binPointSetOverGrid on the checked world)
    // A stamp's copy (docs/language.md, "Stamps"): read at the stamp's frame positions, not the
    // world's, so `bins` cover the frame's box, fixed at check time, and every backend reads them
    // as they are instead of binning the set over its grid.
    bool binnedInFrame = false;
};

// The float operations both backends perform, in this order (lsystem_carve.glsl mirrors them with
// every result `precise`): squared distances (a centre's times scale * scale), the nearest kept
// by `<`, one sqrt at the end.
float centreDistanceSquared(glm::vec3 p, glm::vec3 centre, float scale);
float segmentDistanceSquared(glm::vec3 p, const PointSetSegment& segment);

// The bins of `set` over cells firstCell .. firstCell + cellCount - 1. Throws
// PointSetLimitError before covering more than kMaxPointSetCells cells, testing more than
// kMaxPointSetCellTests (item, cell) pairs of a kind, or storing more than maxEntries list
// entries in all or more than maxPerCell in one cell's list.
PointBins binPointSet(const PointSet& set, glm::ivec3 firstCell, glm::ivec3 cellCount, int32_t cellSize,
                      uint64_t maxEntries, uint32_t maxPerCell);
// The bins every backend uses: kPointSetCellSize cells covering the grid gridOrigin ..
// gridOrigin + gridSize - 1.
PointBins binPointSetOverGrid(const PointSet& set, glm::ivec3 gridOrigin, glm::ivec3 gridSize, uint64_t maxEntries,
                              uint32_t maxPerCell);

struct PointSetLimitError {
    const char* limit; // "cells", "cellTests", "entries", "perCell" or "words"
    uint64_t amount;   // how many were about to be stored (at least limit + 1)
    uint64_t cap;
};

// The list entries one loop iteration of a kernel's lookup visits (lsystem_carve.glsl's
// POINT_SET_BLOCK: 8, or 1 in field kernels whose lists allow it, codegen's
// fieldPointSetListBlock), and the loop iterations a lookup in `bins` takes at most: both lists
// of its fullest cells, a block per iteration, plus the test that ends each loop.
constexpr uint32_t kPointSetListBlock = 8;
uint64_t pointSetLookupIterations(const PointBins& bins, uint32_t block = kPointSetListBlock);

// The node's value at p from `bins` (a position outside the bins' cells: from every point).
glm::vec2 pointSetDistances(const PointSet& set, const PointBins& bins, glm::vec3 p);

// Whether p lies within set.clearance of a segment, from pointSetDistances's float distance (a
// kernel compares pointSetDistances(set, p).y with the header's clearance word the same way).
bool pointSetClearance(const PointSet& set, glm::vec3 p);

// Whether some centre (x) or segment (y) could lie within its reach of a point of the box
// [lo, hi] (conservative: true may be wrong, false never is).
glm::bvec2 pointSetReaches(const PointSet& set, glm::dvec3 lo, glm::dvec3 hi);

// `set`'s points moved by `by`, each coordinate rounded to float once, without lists.
std::shared_ptr<PointSet> movedPointSet(const PointSet& set, glm::dvec3 by);

// The box outside which the node's value is its caps (every centre's and segment's reach around
// it), in the set's coordinates; false for a set without points.
bool pointSetSupport(const PointSet& set, glm::dvec3& lo, glm::dvec3& hi);

// Bounds on the lists of one binning: list entries over all cells, and centres or segments one
// cell lists (the length of a kernel's loop per voxel, before its early exit).
constexpr uint64_t kMaxPointSetListEntries = uint64_t(1) << 24;
constexpr uint32_t kMaxPointSetPerCell = uint32_t(1) << 13;
// (item, cell) pairs one binning tests for each kind (its items' bounding boxes in cells).
constexpr uint64_t kMaxPointSetCellTests = uint64_t(1) << 26;
// Cells one binning covers (each holds a list start per kind): a 4096x512x4096 grid in 8^3 cells.
constexpr uint64_t kMaxPointSetCells = uint64_t(1) << 24;

// The storage buffer of kBindingPointSets (layout in compiler/shaders/lsystem_carve.glsl): every
// set binned over the grid (binPointSetOverGrid), a stamp's copy with its own lists (binnedInFrame). Throws PointSetLimitError past the bounds above
// or a buffer of 2^31 words.
std::vector<int32_t> pointSetWords(std::span<const std::shared_ptr<const PointSet>> sets, glm::ivec3 gridOrigin,
                                   glm::ivec3 gridSize);

} // namespace voxc
