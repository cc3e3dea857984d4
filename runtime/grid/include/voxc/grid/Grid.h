#pragma once
// Voxel storage. DenseGrid is the interpreter's plain array; ChunkedGrid is the runtime's
// chunk-major layout, identical to the GPU buffer, with chunks aligned to world coordinates
// (so a grid whose origin is not a multiple of the chunk size straddles chunks).
#include "voxc/core/AtomicWrite.h"
#include "voxc/program/Program.h"

#include <cstdint>
#include <string>
#include <span>
#include <vector>

namespace voxc {

// Every grid carries two channels per voxel, at the same index: a float density and an 8-bit
// material id (voxc::Material; kMaterialNone = 0 until something writes one).
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
    uint8_t materialAt(glm::ivec3 p) const { return materials_[index(p)]; }
    uint8_t& materialAt(glm::ivec3 p) { return materials_[index(p)]; }
    const std::vector<uint8_t>& materials() const { return materials_; }
    std::vector<uint8_t>& materials() { return materials_; }

private:
    glm::ivec3 size_;
    std::vector<float> data_;
    std::vector<uint8_t> materials_;
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
    uint8_t materialAt(glm::ivec3 local) const { return materials_[layout_.address(local)]; }
    uint8_t& materialAt(glm::ivec3 local) { return materials_[layout_.address(local)]; }
    std::vector<uint8_t>& materials() { return materials_; }
    const std::vector<uint8_t>& materials() const { return materials_; }

    DenseGrid toDense() const;  // both channels
    static ChunkedGrid fromDense(const DenseGrid& grid, const ChunkLayout& layout);

private:
    ChunkLayout layout_;
    std::vector<float> data_;
    std::vector<uint8_t> materials_; // same addresses as data_
};

// NumPy .npy, float32, C order, shape (sx, sy, sz): arr[x,y,z] is voxel (x,y,z). Written atomically;
// the OutputFiles overloads add the file to a set the caller commits (voxc/core/AtomicWrite.h).
// Densities only; materials are a file of their own.
void writeNpy(const std::string& path, const DenseGrid& grid);
void writeNpy(OutputFiles& outputs, const std::string& path, const DenseGrid& grid);
DenseGrid readNpy(const std::string& path); // materials all kMaterialNone
// Any float32 box in DenseGrid's order (x fastest; values.size() = sx*sy*sz), written the same way.
void writeFloatNpy(OutputFiles& outputs, const std::string& path, glm::ivec3 size, std::span<const float> values);

// The material channel as NumPy .npy, uint8 ('|u1'), same shape and order. Written atomically.
void writeMaterialNpy(const std::string& path, const DenseGrid& grid);
void writeMaterialNpy(OutputFiles& outputs, const std::string& path, const DenseGrid& grid);
// Reads such a file into the materials of `grid` (UserError when the shape differs).
void readMaterialNpy(const std::string& path, DenseGrid& grid);

} // namespace voxc
