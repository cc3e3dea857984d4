#pragma once
// The solid/air side of every sample in a box of a grid, one bit per sample, in rows along x: the
// meshers find the cells the surface crosses from these with word-wide bit operations (64 cells at
// a time), so uniform regions cost one streaming pass over their densities and nothing more.
#include "voxc/grid/Grid.h"

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace voxc::mesh_bits {

// A density as the meshers read it: not finite reads 0 (as the pipeline stores it), and so does
// the outside of the grid (air for iso >= 0).
inline bool solidDensity(float d, float iso) { return (std::isfinite(d) ? d : 0.0f) > iso; }

struct SignBits {
    glm::ivec3 first{0};  // grid-local sample of bit 0 of row 0
    glm::ivec3 extent{0}; // samples per axis: bits per row (x), rows per slice (y), slices (z)
    size_t words = 0;     // 64-bit words per row; the last word holds no sample (it reads as 0)
    // Not zeroed up front: each worker writes its rows whole (and so first touches their pages).
    std::unique_ptr<uint64_t[]> bits;
    size_t samplesRead = 0; // the densities classification read (the rest came from tile ranges)

    const uint64_t* row(int y, int z) const { return bits.get() + (size_t(z) * size_t(extent.y) + size_t(y)) * words; }
    uint64_t* row(int y, int z) { return bits.get() + (size_t(z) * size_t(extent.y) + size_t(y)) * words; }
};

// Classifies the samples [first, first + extent) of `grid` (outside the grid: air unless iso < 0),
// solid bit = density > iso, on the chunk workers; with AVX2 when the CPU has it (same bits).
// Given the grid's tile ranges, a tile that lies on one side of iso is classified from its range,
// without reading its densities (the same bits).
SignBits classifySamples(const ChunkedGrid& grid, float iso, glm::ivec3 first, glm::ivec3 extent, const TileRanges* ranges);

// "avx2" or "scalar": which sample classification this CPU runs.
const char* classificationPath();

} // namespace voxc::mesh_bits
