#include "SignBits.h"

#include "ChunkWorkers.h"
#include "voxc/core/HugePages.h"
#include "voxc/core/Simd.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define VOXC_MESH_X86 1
#endif

namespace voxc::mesh_bits {
namespace {

// ORs the low `count` bits of `value` into the row at bit `bit` (rows are word-aligned, so two
// threads writing different rows never share a word).
inline void putBits(uint64_t* row, int bit, uint64_t value, int count) {
    const int word = bit >> 6, shift = bit & 63;
    row[word] |= value << shift;
    if (shift + count > 64) row[word + 1] |= value >> (64 - shift);
}

void classifyScalar(const float* densities, int count, float iso, uint64_t* row, int bit) {
    for (int i = 0; i < count; ++i)
        if (solidDensity(densities[i], iso)) row[(bit + i) >> 6] |= uint64_t(1) << ((bit + i) & 63);
}

#ifdef VOXC_MESH_X86
// Eight samples per compare: solid = finite && d > iso, or, when 0 > iso, not finite || d > iso
// (a density that is not finite reads 0). The same bits as classifyScalar.
__attribute__((target("avx2"))) void classifyAvx2(const float* densities, int count, float iso, uint64_t* row, int bit) {
    const __m256 isoV = _mm256_set1_ps(iso);
    const __m256 magnitude = _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff));
    const __m256 infinity = _mm256_set1_ps(INFINITY);
    const bool zeroIsSolid = 0.0f > iso;
    int i = 0;
    for (; i + 8 <= count; i += 8) {
        const __m256 d = _mm256_loadu_ps(densities + i);
        const __m256 above = _mm256_cmp_ps(d, isoV, _CMP_GT_OQ);
        const __m256 finite = _mm256_cmp_ps(_mm256_and_ps(d, magnitude), infinity, _CMP_LT_OQ);
        const __m256 solid = zeroIsSolid ? _mm256_or_ps(above, _mm256_xor_ps(finite, _mm256_castsi256_ps(_mm256_set1_epi32(-1))))
                                         : _mm256_and_ps(above, finite);
        putBits(row, bit + i, uint64_t(unsigned(_mm256_movemask_ps(solid))), 8);
    }
    classifyScalar(densities + i, count - i, iso, row, bit + i);
}
#endif

using Classify = void (*)(const float*, int, float, uint64_t*, int);

Classify classifier() {
#ifdef VOXC_MESH_X86
    if (hostSimd() >= Simd::Avx2) return classifyAvx2;
#endif
    return classifyScalar;
}

} // namespace

const char* classificationPath() { return classifier() == classifyScalar ? "scalar" : "avx2"; }

SignBits classifySamples(const ChunkedGrid& grid, float iso, glm::ivec3 first, glm::ivec3 extent, const TileRanges* ranges) {
    const ChunkLayout& layout = grid.layout();
    SignBits signs;
    signs.first = first;
    signs.extent = extent;
    signs.words = size_t(extent.x + 63) / 64 + 1;
    const size_t words = signs.words * size_t(extent.y) * size_t(extent.z);
    signs.bits.reset(new uint64_t[words]);
    adviseHugePages(signs.bits.get(), words * sizeof(uint64_t));
    const Classify classify = classifier();
    const bool outsideSolid = 0.0f > iso;
    // Grid-local x range of the row inside the grid: [inBegin, inEnd).
    const int inBegin = std::max(first.x, 0), inEnd = std::min(first.x + extent.x, layout.gridSize.x);
    const float* data = grid.data().data();
    const int chunkMask = layout.chunkSize - 1;
    constexpr int tileSide = 1 << TileRanges::kShift;
    std::atomic<size_t> samplesRead{0};

    // Rows of one band (the rows of a tile, or of a chunk without tile ranges) read the same tiles
    // in the same chunks: the band's solid tiles are a template of bits and its mixed tiles a list
    // of contiguous runs (within one chunk's row) to classify, made once per band and slice.
    const int bandShift = ranges ? std::min(TileRanges::kShift, layout.chunkShift) : layout.chunkShift;
    struct Run {
        int gx, count;
        size_t address; // of sample (gx, band's first row, gz)
    };

    forEachChunk(size_t(extent.z), [&](size_t slice) {
        const int z = int(slice), gz = first.z + z;
        size_t read = 0;
        std::vector<uint64_t> solidTemplate(signs.words);
        std::vector<Run> runs;
        int bandFirstY = 0, band = INT32_MIN;
        for (int y = 0; y < extent.y; ++y) {
            const int gy = first.y + y;
            uint64_t* row = signs.row(y, z);
            std::fill_n(row, signs.words, uint64_t(0));
            const bool rowInside = gy >= 0 && gy < layout.gridSize.y && gz >= 0 && gz < layout.gridSize.z;
            if (outsideSolid) {
                for (int x = 0; x < extent.x; ++x)
                    if (!rowInside || first.x + x < inBegin || first.x + x >= inEnd) row[x >> 6] |= uint64_t(1) << (x & 63);
            }
            if (!rowInside) continue;
            const int worldY = layout.gridOrigin.y + gy, worldZ = layout.gridOrigin.z + gz;
            if ((worldY >> bandShift) != band) {
                band = worldY >> bandShift;
                bandFirstY = gy;
                std::fill(solidTemplate.begin(), solidTemplate.end(), uint64_t(0));
                runs.clear();
                // Along x a chunk's row is contiguous: a run never crosses a chunk, and with tile
                // ranges each tile's segment is solid, air or classified.
                for (int gx = inBegin; gx < inEnd;) {
                    const int worldX = layout.gridOrigin.x + gx;
                    int count = std::min(layout.chunkSize - (worldX & chunkMask), inEnd - gx);
                    if (ranges) {
                        count = std::min(count, tileSide - (worldX & (tileSide - 1)));
                        const TileRanges::Range& range = ranges->at(glm::ivec3(worldX, worldY, worldZ) >> TileRanges::kShift);
                        if (range.low > iso) {
                            putBits(solidTemplate.data(), gx - first.x, (uint64_t(1) << count) - 1, count);
                            gx += count;
                            continue;
                        }
                        if (range.high <= iso) {
                            gx += count;
                            continue;
                        }
                    }
                    if (!runs.empty() && runs.back().gx + runs.back().count == gx && (worldX & chunkMask) != 0)
                        runs.back().count += count;
                    else
                        runs.push_back({gx, count, layout.address({gx, gy, gz})});
                    gx += count;
                }
            }
            for (size_t w = 0; w < signs.words; ++w) row[w] |= solidTemplate[w];
            // Inside a chunk the next row along y is chunkSize samples on.
            const size_t rowOffset = size_t(gy - bandFirstY) * size_t(layout.chunkSize);
            for (const Run& run : runs) {
                classify(data + run.address + rowOffset, run.count, iso, row, run.gx - first.x);
                read += size_t(run.count);
            }
        }
        samplesRead += read;
        return true;
    });
    signs.samplesRead = samplesRead.load();
    return signs;
}

} // namespace voxc::mesh_bits
