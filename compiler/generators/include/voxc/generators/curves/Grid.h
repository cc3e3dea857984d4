#pragma once
// The solve box: a dense grid, one solve cell per voxel, whose cell (i,j,k) samples the voxel
// min + (i,j,k) (spec A3.1). Fields are float32 arrays in x-fastest order, the layout a GLSL
// kernel indexes the same way.
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace voxc::curves {

struct Box {
    glm::ivec3 min{0};
    glm::ivec3 size{1}; // cells per axis, each >= 1

    uint64_t cellCount() const { return uint64_t(size.x) * uint64_t(size.y) * uint64_t(size.z); }
    size_t index(int32_t x, int32_t y, int32_t z) const { return (size_t(z) * size_t(size.y) + size_t(y)) * size_t(size.x) + size_t(x); }
    bool contains(int32_t x, int32_t y, int32_t z) const {
        return x >= 0 && y >= 0 && z >= 0 && x < size.x && y < size.y && z < size.z;
    }
};

// The six face neighbours in the fixed order every loop uses: -x, +x, -y, +y, -z, +z.
inline constexpr int32_t kNeighbourOffsets[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};

struct Field3 {
    Box box;
    std::vector<float> values;

    Field3() = default;
    explicit Field3(const Box& box_, float fill = 0.0f) : box(box_), values(box_.cellCount(), fill) {}
    float& at(int32_t x, int32_t y, int32_t z) { return values[box.index(x, y, z)]; }
    float at(int32_t x, int32_t y, int32_t z) const { return values[box.index(x, y, z)]; }
};

} // namespace voxc::curves
