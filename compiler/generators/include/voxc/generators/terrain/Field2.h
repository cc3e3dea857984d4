#pragma once
// A dense 2D float32 field, row-major (x fastest), the storage of every terrain level and erosion
// channel. Reads outside the grid clamp to the edge (the thesis's "closest value").
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace voxc::terrain {

struct Field2 {
    Field2() = default;
    Field2(int32_t width_, int32_t height_, float fill = 0.0f)
        : width(width_), height(height_), values(size_t(width_) * size_t(height_), fill) {}

    int32_t width = 0;
    int32_t height = 0;
    std::vector<float> values;

    size_t index(int32_t x, int32_t y) const { return size_t(x) + size_t(width) * size_t(y); }
    float at(int32_t x, int32_t y) const { return values[index(x, y)]; }
    float& at(int32_t x, int32_t y) { return values[index(x, y)]; }
    float clamped(int32_t x, int32_t y) const {
        return at(std::clamp(x, 0, width - 1), std::clamp(y, 0, height - 1));
    }
};

} // namespace voxc::terrain
