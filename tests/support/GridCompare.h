#pragma once
// Bit-for-bit comparison of two voxel grids (densities and materials) for tests, reporting the
// first few differences.
#include "voxc/grid/Grid.h"

#include <cstring>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace voxc::test {

// Number of voxels whose float bit patterns differ; adds a failure for each of the first five.
inline size_t countBitDifferences(const DenseGrid& expected, const DenseGrid& actual) {
    EXPECT_EQ(expected.size(), actual.size());
    if (expected.size() != actual.size()) return expected.data().size();
    size_t differences = 0;
    const glm::ivec3 size = expected.size();
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const float a = expected.at({x, y, z});
                const float b = actual.at({x, y, z});
                if (std::memcmp(&a, &b, sizeof(float)) != 0 && differences++ < 5)
                    ADD_FAILURE() << fmt::format("voxel ({},{},{}): expected {} got {}", x, y, z, a, b);
            }
    return differences;
}

// Number of voxels whose material ids differ; adds a failure for each of the first five.
inline size_t countMaterialDifferences(const DenseGrid& expected, const DenseGrid& actual) {
    EXPECT_EQ(expected.size(), actual.size());
    if (expected.size() != actual.size()) return expected.materials().size();
    size_t differences = 0;
    const glm::ivec3 size = expected.size();
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const int a = expected.materialAt({x, y, z});
                const int b = actual.materialAt({x, y, z});
                if (a != b && differences++ < 5)
                    ADD_FAILURE() << fmt::format("voxel ({},{},{}): expected material {} got {}", x, y, z, a, b);
            }
    return differences;
}

// Densities bit for bit and materials id for id: the number of voxels that differ in either.
inline size_t countVoxelDifferences(const DenseGrid& expected, const DenseGrid& actual) {
    return countBitDifferences(expected, actual) + countMaterialDifferences(expected, actual);
}

} // namespace voxc::test
