#pragma once
// Voxel storage. DenseGrid is the interpreter's plain array; ChunkedGrid is the runtime's
// chunk-major layout, identical to the GPU buffer, with chunks aligned to world coordinates
// (so a grid whose origin is not a multiple of the chunk size straddles chunks).
#include "voxc/program/Program.h"

#include <cstdint>
#include <string>
#include <vector>

namespace voxc {

class DenseGrid {
public:
    explicit DenseGrid(glm::ivec3 size, float fill = 0.0f);
    glm::ivec3 size() const { return size_; }
    // x fastest: index = x + sx*(y + sy*z)
    size_t index(glm::ivec3 p) const { return size_t(p.x) + size_t(size_.x) * (size_t(p.y) + size_t(size_.y) * size_t(p.z)); }
    float at(glm::ivec3 p) const { return data_[index(p)]; }
    float& at(glm::ivec3 p) { return data_[index(p)]; }
    bool inside(glm::ivec3 p) const;
    const std::vector<float>& data() const { return data_; }
    std::vector<float>& data() { return data_; }

private:
    glm::ivec3 size_;
    std::vector<float> data_;
};

// Maps grid-local voxels to (slot, offset) in a chunk-major buffer.
struct ChunkLayout {
    glm::ivec3 gridOrigin{0};  // world coordinate of local (0,0,0)
    glm::ivec3 gridSize{0};
    int32_t chunkSize = 32;     // power of two
    int32_t chunkShift = 5;     // log2(chunkSize)
    glm::ivec3 chunkBase{0};    // world chunk coordinate of table entry 0
    glm::ivec3 chunkCount{0};   // table extents

    static ChunkLayout make(glm::ivec3 gridOrigin, glm::ivec3 gridSize, int32_t chunkSize);
    size_t chunkVoxels() const { return size_t(chunkSize) * chunkSize * chunkSize; }
    size_t chunkTotal() const { return size_t(chunkCount.x) * chunkCount.y * chunkCount.z; }
    // Dense table: slot of table entry t is t (the table exists so sparse grids can come later).
    std::vector<int32_t> chunkTable() const;
    size_t address(glm::ivec3 local) const;
};

class ChunkedGrid {
public:
    explicit ChunkedGrid(const ChunkLayout& layout);
    const ChunkLayout& layout() const { return layout_; }
    float at(glm::ivec3 local) const { return data_[layout_.address(local)]; }
    float& at(glm::ivec3 local) { return data_[layout_.address(local)]; }
    std::vector<float>& data() { return data_; }
    const std::vector<float>& data() const { return data_; }

    DenseGrid toDense() const;
    static ChunkedGrid fromDense(const DenseGrid& grid, const ChunkLayout& layout);

private:
    ChunkLayout layout_;
    std::vector<float> data_;
};

// NumPy .npy, float32, C order, shape (sx, sy, sz): arr[x,y,z] is voxel (x,y,z). Written atomically.
void writeNpy(const std::string& path, const DenseGrid& grid);
DenseGrid readNpy(const std::string& path);

} // namespace voxc
