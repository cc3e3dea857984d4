#include "voxc/grid/Grid.h"

#include "voxc/core/Errors.h"

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
    return chunked;
}

} // namespace voxc
