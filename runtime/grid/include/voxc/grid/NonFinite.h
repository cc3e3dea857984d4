#pragma once
// The one rule for non-finite densities (docs/language.md, "Non-finite values"): a field stage
// stores 0 where its field's value is NaN or infinite, a grammar stores 0 where a written value
// (after the clamp) is not finite, and each stage counts its replacements. The interpreter
// applies it here, the kernels in compiler/shaders/nonfinite.glsl, so the grid after every stage
// holds only finite densities on both backends.
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>

namespace voxc {

// The replacements of one stage.
struct NonFiniteCount {
    uint64_t count = 0;
    // The lowest grid index x + sx * (y + sy * z) among the replaced voxels (when count > 0);
    // the order the writes happened in does not matter, so both backends agree.
    uint64_t firstIndex = 0;

    // `value` when finite; else 0, counted at grid index `index`.
    float replace(float value, uint64_t index) {
        if (std::isfinite(value)) return value;
        if (count == 0 || index < firstIndex) firstIndex = index;
        ++count;
        return 0.0f;
    }

    // values[i] = replace(values[i], first + i) for i < n: a quick test of the whole row first,
    // as a row is almost always finite.
    void replaceRow(float* values, int n, uint64_t first) {
        uint32_t nonFinite = 0; // (exponent bits all set: infinite or NaN; integer tests vectorise)
        for (int i = 0; i < n; ++i) nonFinite |= uint32_t((std::bit_cast<uint32_t>(values[i]) & 0x7f800000u) == 0x7f800000u);
        if (nonFinite == 0) return;
        for (int i = 0; i < n; ++i) values[i] = replace(values[i], first + uint64_t(i));
    }
};

// The grid-local voxel of grid index `index` in a grid of `size` voxels.
inline glm::ivec3 gridPosition(uint64_t index, glm::ivec3 size) {
    const uint64_t sx = uint64_t(size.x), sy = uint64_t(size.y);
    return {int(index % sx), int(index / sx % sy), int(index / (sx * sy))};
}

} // namespace voxc
