#include "voxc/grid/Grid.h"

#include <gtest/gtest.h>
#include <vector>

namespace voxc {
namespace {

struct LayoutCase {
    glm::ivec3 origin;
    int32_t chunkSize;
};

std::vector<LayoutCase> layoutCases() {
    std::vector<LayoutCase> cases;
    for (glm::ivec3 origin : {glm::ivec3(0, 0, 0), glm::ivec3(-37, -5, -100), glm::ivec3(100003, 7, -65541)})
        for (int32_t c : {8, 16, 32}) cases.push_back({origin, c});
    return cases;
}

int floorDiv(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

TEST(grid_ChunkLayout, makeComputesChunkTableExtents) {
    for (const LayoutCase& c : layoutCases()) {
        const glm::ivec3 size(45, 23, 70);
        const ChunkLayout layout = ChunkLayout::make(c.origin, size, c.chunkSize);
        EXPECT_EQ(1 << layout.chunkShift, c.chunkSize);
        for (int a = 0; a < 3; ++a) {
            EXPECT_EQ(layout.chunkBase[a], floorDiv(c.origin[a], c.chunkSize));
            EXPECT_EQ(layout.chunkCount[a], floorDiv(c.origin[a] + size[a] - 1, c.chunkSize) - layout.chunkBase[a] + 1);
        }
        const std::vector<int32_t> table = layout.chunkTable();
        ASSERT_EQ(table.size(), layout.chunkTotal());
        for (size_t i = 0; i < table.size(); ++i) EXPECT_EQ(table[i], int32_t(i));
    }
}

TEST(grid_ChunkLayout, addressesAreDistinctAndInRange) {
    for (const LayoutCase& c : layoutCases()) {
        const glm::ivec3 size(45, 23, 70);
        const ChunkLayout layout = ChunkLayout::make(c.origin, size, c.chunkSize);
        const size_t total = layout.chunkTotal() * layout.chunkVoxels();
        std::vector<bool> used(total, false);
        for (int z = 0; z < size.z; ++z)
            for (int y = 0; y < size.y; ++y)
                for (int x = 0; x < size.x; ++x) {
                    const size_t a = layout.address({x, y, z});
                    ASSERT_LT(a, total);
                    ASSERT_FALSE(used[a]) << "address reused at origin " << c.origin.x << " chunk " << c.chunkSize;
                    used[a] = true;
                }
    }
}

TEST(grid_ChunkLayout, addressDecomposesIntoWorldAlignedChunks) {
    for (const LayoutCase& c : layoutCases()) {
        const ChunkLayout layout = ChunkLayout::make(c.origin, {40, 9, 33}, c.chunkSize);
        for (glm::ivec3 local : {glm::ivec3(0, 0, 0), glm::ivec3(39, 8, 32), glm::ivec3(17, 3, 29)}) {
            const glm::ivec3 world = c.origin + local;
            const size_t address = layout.address(local);
            const size_t slot = address / layout.chunkVoxels();
            const size_t inside = address % layout.chunkVoxels();
            const glm::ivec3 entry(int(slot % size_t(layout.chunkCount.x)),
                                   int(slot / size_t(layout.chunkCount.x) % size_t(layout.chunkCount.y)),
                                   int(slot / (size_t(layout.chunkCount.x) * size_t(layout.chunkCount.y))));
            const int cs = c.chunkSize;
            const glm::ivec3 offset(int(inside % size_t(cs)), int(inside / size_t(cs) % size_t(cs)), int(inside / size_t(cs * cs)));
            for (int a = 0; a < 3; ++a) {
                EXPECT_EQ(entry[a] + layout.chunkBase[a], floorDiv(world[a], cs));
                EXPECT_EQ(offset[a], world[a] - floorDiv(world[a], cs) * cs);
            }
        }
    }
}

TEST(grid_ChunkedGrid, denseRoundTripPreservesEveryVoxel) {
    for (const LayoutCase& c : layoutCases()) {
        DenseGrid dense({19, 34, 11});
        for (size_t i = 0; i < dense.data().size(); ++i) dense.data()[i] = float(i) * 0.25f - 7.0f;
        const ChunkLayout layout = ChunkLayout::make(c.origin, dense.size(), c.chunkSize);
        const ChunkedGrid chunked = ChunkedGrid::fromDense(dense, layout);
        EXPECT_EQ(chunked.data().size(), layout.chunkTotal() * layout.chunkVoxels());
        EXPECT_EQ(chunked.at({3, 20, 7}), dense.at({3, 20, 7}));
        EXPECT_EQ(chunked.toDense().data(), dense.data());
    }
}

TEST(grid_DenseGrid, indexIsXFastestAndInsideIsHalfOpen) {
    DenseGrid grid({4, 5, 6}, 2.0f);
    EXPECT_EQ(grid.data().size(), 120u);
    EXPECT_EQ(grid.index({1, 0, 0}), 1u);
    EXPECT_EQ(grid.index({0, 1, 0}), 4u);
    EXPECT_EQ(grid.index({0, 0, 1}), 20u);
    EXPECT_EQ(grid.at({3, 4, 5}), 2.0f);
    EXPECT_TRUE(grid.inside({3, 4, 5}));
    EXPECT_FALSE(grid.inside({4, 0, 0}));
    EXPECT_FALSE(grid.inside({0, -1, 0}));
}

} // namespace
} // namespace voxc
