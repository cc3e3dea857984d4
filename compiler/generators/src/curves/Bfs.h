#pragma once
// BFS helpers shared by the layer-by-layer propagations (normal fill, material, surface): a
// layer reads only cells set in earlier layers, so the order within a layer never matters.
#include "voxc/generators/curves/Grid.h"

#include <algorithm>

namespace voxc::curves {

inline glm::ivec3 coordinates(const Box& b, size_t i) {
    return {int32_t(i % size_t(b.size.x)), int32_t(i / size_t(b.size.x) % size_t(b.size.y)),
            int32_t(i / (size_t(b.size.x) * size_t(b.size.y)))};
}

// Cells of the next layer: those with `done` unset that neighbour a cell of `front`, once each
// (stamp[j] == layer marks them), ascending.
inline std::vector<size_t> nextLayer(const Box& b, const std::vector<size_t>& front, const std::vector<uint8_t>& done,
                                     std::vector<int32_t>& stamp, int32_t layer) {
    std::vector<size_t> out;
    for (size_t i : front) {
        const glm::ivec3 p = coordinates(b, i);
        for (const auto& d : kNeighbourOffsets) {
            if (!b.contains(p.x + d[0], p.y + d[1], p.z + d[2])) continue;
            const size_t j = b.index(p.x + d[0], p.y + d[1], p.z + d[2]);
            if (!done[j] && stamp[j] != layer) stamp[j] = layer, out.push_back(j);
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace voxc::curves
