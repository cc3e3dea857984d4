#pragma once
// Voxel storage. DenseGrid is the interpreter's plain array; ChunkedGrid is the runtime's
// chunk-major layout, identical to the GPU buffer, with chunks aligned to world coordinates
// (so a grid whose origin is not a multiple of the chunk size straddles chunks).
#include "voxc/core/AtomicWrite.h"
#include "voxc/program/Program.h"

#include <cstdint>
#include <optional>
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

// The least and greatest density of every world-aligned 8^3 tile of a grid, counting only the
// tile's voxels inside the grid and reading a density that is not finite as 0 (as the meshers
// read it): a tile whose least density is above an iso, or whose greatest is not, lies on one
// side of it, and the mesher classifies it without reading its voxels.
struct TileRanges {
    static constexpr int kShift = 3; // tiles of 8^3 voxels
    struct Range {
        float low, high;
    };
    glm::ivec3 first{0}; // world tile coordinate of entry 0 (gridOrigin >> kShift)
    glm::ivec3 count{0}; // tiles per axis that hold voxels of the grid
    std::vector<Range> ranges;

    size_t index(glm::ivec3 worldTile) const {
        const glm::ivec3 t = worldTile - first;
        return size_t(t.x) + size_t(count.x) * (size_t(t.y) + size_t(count.y) * size_t(t.z));
    }
    const Range& at(glm::ivec3 worldTile) const { return ranges[index(worldTile)]; }
    Range& at(glm::ivec3 worldTile) { return ranges[index(worldTile)]; }
};

class ChunkedGrid {
public:
    explicit ChunkedGrid(const ChunkLayout& layout);
    const ChunkLayout& layout() const { return layout_; }
    float at(glm::ivec3 local) const { return data_[layout_.address(local)]; }
    // Writable access to the densities forgets the tile ranges (they may no longer hold).
    float& at(glm::ivec3 local) {
        tileRanges_.reset();
        return data_[layout_.address(local)];
    }
    std::vector<float>& data() {
        tileRanges_.reset();
        return data_;
    }
    const std::vector<float>& data() const { return data_; }
    // The densities' tile ranges where the producer of the grid recorded them, else null.
    const TileRanges* tileRanges() const { return tileRanges_ ? &*tileRanges_ : nullptr; }
    // Records the tile ranges of the densities as they are now (one pass over them).
    void recordTileRanges();
    // Records them after a change of the grid-local voxels [first, last] (inclusive) only: `before`
    // (the ranges taken before the change) with the tiles that box touches summarised again (none
    // for an empty box: last < first on some axis).
    void recordTileRanges(TileRanges before, glm::ivec3 first, glm::ivec3 last);
    // Copies the layout's chunk-major densities (data().size() floats, e.g. a device buffer
    // mapped for reading) into the grid and records their tile ranges in the same pass.
    void loadDensities(const float* chunkMajor);
    uint8_t materialAt(glm::ivec3 local) const { return materials_[layout_.address(local)]; }
    uint8_t& materialAt(glm::ivec3 local) { return materials_[layout_.address(local)]; }
    std::vector<uint8_t>& materials() { return materials_; }
    const std::vector<uint8_t>& materials() const { return materials_; }

    DenseGrid toDense() const;  // both channels
    static ChunkedGrid fromDense(const DenseGrid& grid, const ChunkLayout& layout);

private:
    // Copies `source` into data_ when `copyTo` is data_.data(), and records the tile ranges of `source`.
    void summarize(const float* source, float* copyTo);

    ChunkLayout layout_;
    std::vector<float> data_;
    std::vector<uint8_t> materials_; // same addresses as data_
    std::optional<TileRanges> tileRanges_;
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
