#pragma once
// Bit-for-bit comparison of two voxel grids for tests, reporting the first few differences.
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

} // namespace voxc::test
