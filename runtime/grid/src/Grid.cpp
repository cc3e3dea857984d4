#include "voxc/grid/Grid.h"

#include "voxc/core/Errors.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>
#include <numeric>

namespace voxc {

DenseGrid::DenseGrid(glm::ivec3 size, float fill) : size_(size) {
    VOXC_ASSERT(size.x >= 0 && size.y >= 0 && size.z >= 0);
    data_.assign(size_t(size.x) * size_t(size.y) * size_t(size.z), fill);
    materials_.assign(data_.size(), kMaterialNone);
}

bool DenseGrid::inside(glm::ivec3 p) const {
    return p.x >= 0 && p.y >= 0 && p.z >= 0 && p.x < size_.x && p.y < size_.y && p.z < size_.z;
}

ChunkLayout ChunkLayout::make(glm::ivec3 gridOrigin, glm::ivec3 gridSize, int32_t chunkSize) {
    VOXC_ASSERT(chunkSize > 0 && (chunkSize & (chunkSize - 1)) == 0);
    VOXC_ASSERT(gridSize.x > 0 && gridSize.y > 0 && gridSize.z > 0);
    ChunkLayout layout;
    layout.gridOrigin = gridOrigin;
    layout.gridSize = gridSize;
    layout.chunkSize = chunkSize;
    layout.chunkShift = 0;
    while ((1 << layout.chunkShift) < chunkSize) ++layout.chunkShift;
    // C++20 defines >> on negative ints as arithmetic, i.e. floor division by 2^shift,
    // which is also what the GLSL kernels compute; chunks are aligned to world coordinates.
    const glm::ivec3 last = gridOrigin + gridSize - 1;
    layout.chunkBase = gridOrigin >> layout.chunkShift;
    layout.chunkCount = (last >> layout.chunkShift) - layout.chunkBase + 1;
    return layout;
}

std::vector<int32_t> ChunkLayout::chunkTable() const {
    std::vector<int32_t> table(chunkTotal());
    std::iota(table.begin(), table.end(), 0);
    return table;
}

size_t ChunkLayout::address(glm::ivec3 local) const {
    const glm::ivec3 world = gridOrigin + local;
    const glm::ivec3 entry = (world >> chunkShift) - chunkBase;
    const glm::ivec3 inside = world & (chunkSize - 1);
    // The table is the identity, so the slot is the dense table index itself.
    const size_t slot = size_t(entry.x) + size_t(chunkCount.x) * (size_t(entry.y) + size_t(chunkCount.y) * size_t(entry.z));
    const size_t c = size_t(chunkSize);
    return slot * chunkVoxels() + size_t(inside.x) + c * (size_t(inside.y) + c * size_t(inside.z));
}

ChunkedGrid::ChunkedGrid(const ChunkLayout& layout)
    : layout_(layout), data_(layout.chunkTotal() * layout.chunkVoxels(), 0.0f), materials_(data_.size(), kMaterialNone) {}

DenseGrid ChunkedGrid::toDense() const {
    DenseGrid dense(layout_.gridSize);
    const glm::ivec3 s = layout_.gridSize;
    for (int z = 0; z < s.z; ++z)
        for (int y = 0; y < s.y; ++y)
            for (int x = 0; x < s.x; ++x) {
                dense.at({x, y, z}) = at({x, y, z});
                dense.materialAt({x, y, z}) = materialAt({x, y, z});
            }
    return dense;
}

ChunkedGrid ChunkedGrid::fromDense(const DenseGrid& grid, const ChunkLayout& layout) {
    VOXC_ASSERT(grid.size() == layout.gridSize);
    ChunkedGrid chunked(layout);
    const glm::ivec3 s = layout.gridSize;
    for (int z = 0; z < s.z; ++z)
        for (int y = 0; y < s.y; ++y)
            for (int x = 0; x < s.x; ++x) {
                chunked.at({x, y, z}) = grid.at({x, y, z});
                chunked.materialAt({x, y, z}) = grid.materialAt({x, y, z});
            }
    chunked.recordTileRanges();
    return chunked;
}

namespace {

// A density as the meshers read it.
inline float meshedDensity(float d) { return std::isfinite(d) ? d : 0.0f; }

} // namespace

void ChunkedGrid::recordTileRanges() { summarize(data_.data(), nullptr); }

void ChunkedGrid::recordTileRanges(TileRanges before, glm::ivec3 first, glm::ivec3 last) {
    constexpr int kShift = TileRanges::kShift;
    const ChunkLayout& l = layout_;
    if (glm::any(glm::lessThan(last, first))) {
        tileRanges_ = std::move(before);
        return;
    }
    const glm::ivec3 tileFirst = (l.gridOrigin + first) >> kShift, tileLast = (l.gridOrigin + last) >> kShift;
    for (int tz = tileFirst.z; tz <= tileLast.z; ++tz)
        for (int ty = tileFirst.y; ty <= tileLast.y; ++ty)
            for (int tx = tileFirst.x; tx <= tileLast.x; ++tx) {
                const glm::ivec3 tile(tx, ty, tz);
                // The tile's voxels inside the grid, grid-local [low, high].
                const glm::ivec3 low = glm::max(tile * (1 << kShift) - l.gridOrigin, glm::ivec3(0));
                const glm::ivec3 high = glm::min((tile + 1) * (1 << kShift) - l.gridOrigin, l.gridSize) - 1;
                TileRanges::Range range{INFINITY, -INFINITY};
                for (int z = low.z; z <= high.z; ++z)
                    for (int y = low.y; y <= high.y; ++y)
                        for (int x = low.x; x <= high.x; ++x) {
                            const float d = meshedDensity(data_[l.address({x, y, z})]);
                            range.low = std::min(range.low, d);
                            range.high = std::max(range.high, d);
                        }
                before.at(tile) = range;
            }
    tileRanges_ = std::move(before);
}

void ChunkedGrid::loadDensities(const float* chunkMajor) { summarize(chunkMajor, data_.data()); }

void ChunkedGrid::summarize(const float* source, float* copyTo) {
    constexpr int kShift = TileRanges::kShift, kSide = 1 << kShift;
    const ChunkLayout& l = layout_;
    TileRanges tiles;
    tiles.first = l.gridOrigin >> kShift;
    tiles.count = ((l.gridOrigin + l.gridSize - 1) >> kShift) - tiles.first + 1;
    tiles.ranges.assign(size_t(tiles.count.x) * size_t(tiles.count.y) * size_t(tiles.count.z), {INFINITY, -INFINITY});
    const int c = l.chunkSize;
    const size_t chunkVoxels = l.chunkVoxels();
    // Per tile a chunk meets (one when chunks are smaller than tiles), the least and greatest
    // density of each of its eight columns along x: whole tile rows update them lane by lane
    // (vectorised), and the columns are reduced once per chunk.
    const int perAxis = std::max(1, c >> kShift);
    const size_t lanes = size_t(perAxis) * size_t(perAxis) * size_t(perAxis) * kSide;
    std::vector<float> lows(lanes), highs(lanes);
    // In the buffer's order, one chunk at a time: a chunk (128 KiB at size 32) is copied and then
    // read again from the cache, so copying and summarising cost one pass over memory.
    size_t slot = 0;
    for (int cz = 0; cz < l.chunkCount.z; ++cz)
        for (int cy = 0; cy < l.chunkCount.y; ++cy)
            for (int cx = 0; cx < l.chunkCount.x; ++cx, ++slot) {
                const float* chunk = source + slot * chunkVoxels;
                if (copyTo) std::memcpy(copyTo + slot * chunkVoxels, chunk, chunkVoxels * sizeof(float));
                const glm::ivec3 chunkWorld = (l.chunkBase + glm::ivec3(cx, cy, cz)) * c;
                // The chunk's voxels inside the grid, chunk-local [low, high).
                const glm::ivec3 low = glm::max(l.gridOrigin - chunkWorld, glm::ivec3(0));
                const glm::ivec3 high = glm::min(l.gridOrigin + l.gridSize - chunkWorld, glm::ivec3(c));
                if (glm::any(glm::greaterThanEqual(low, high))) continue;
                std::fill(lows.begin(), lows.end(), INFINITY);
                std::fill(highs.begin(), highs.end(), -INFINITY);
                const bool wholeRows = low.x == 0 && high.x == c && c >= kSide;
                for (int z = low.z; z < high.z; ++z)
                    for (int y = low.y; y < high.y; ++y) {
                        const float* row = chunk + size_t(c) * (size_t(y) + size_t(c) * size_t(z));
                        const size_t tileRow = (size_t(z >> kShift) * size_t(perAxis) + size_t(y >> kShift)) * size_t(perAxis);
                        if (wholeRows) {
                            for (int t = 0; t < perAxis; ++t) {
                                float* lo = lows.data() + (tileRow + size_t(t)) * kSide;
                                float* hi = highs.data() + (tileRow + size_t(t)) * kSide;
                                const float* v = row + t * kSide;
                                for (int i = 0; i < kSide; ++i) {
                                    const float d = meshedDensity(v[i]);
                                    lo[i] = std::min(lo[i], d);
                                    hi[i] = std::max(hi[i], d);
                                }
                            }
                        } else {
                            for (int x = low.x; x < high.x; ++x) {
                                const size_t lane = (tileRow + size_t(x >> kShift)) * kSide + size_t(x & (kSide - 1));
                                const float d = meshedDensity(row[x]);
                                lows[lane] = std::min(lows[lane], d);
                                highs[lane] = std::max(highs[lane], d);
                            }
                        }
                    }
                const glm::ivec3 tileFirst = chunkWorld >> kShift;
                size_t t = 0;
                for (int z = 0; z < perAxis; ++z)
                    for (int y = 0; y < perAxis; ++y)
                        for (int x = 0; x < perAxis; ++x, ++t) {
                            const float lo = *std::min_element(lows.begin() + ptrdiff_t(t * kSide), lows.begin() + ptrdiff_t((t + 1) * kSide));
                            const float hi = *std::max_element(highs.begin() + ptrdiff_t(t * kSide), highs.begin() + ptrdiff_t((t + 1) * kSide));
                            if (lo > hi) continue; // no voxel of the grid in this tile
                            TileRanges::Range& r = tiles.at(tileFirst + glm::ivec3(x, y, z));
                            r.low = std::min(r.low, lo);
                            r.high = std::max(r.high, hi);
                        }
            }
    tileRanges_ = std::move(tiles);
}

} // namespace voxc
