#pragma once
// BFS helpers shared by the layer-by-layer propagations (normal fill, material, surface): a
// layer reads only cells set in earlier layers, so the order within a layer never matters.
#include "voxc/generators/curves/Grid.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>

namespace voxc::curves {

inline glm::ivec3 coordinates(const Box& b, size_t i) {
    // 32-bit divisions (a box holds < 2^32 cells): a third of the 64-bit ones' cost.
    const uint32_t index = uint32_t(i), nx = uint32_t(b.size.x), ny = uint32_t(b.size.y);
    const uint32_t row = index / nx;
    return {int32_t(index - row * nx), int32_t(row % ny), int32_t(row / ny)};
}

// Cells of the next layer: those with `done` unset that neighbour a cell of `front`, once each
// (stamp[j] == layer marks them), in the order the front reaches them.
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
    return out;
}

// Whether cell k was set in a layer before `l` (layer[k] in [0, l)): a relaxed atomic load, as
// the other thread of growLayers may be claiming k meanwhile (then it reads -1 or l: not set).
inline bool setBefore(const std::vector<int32_t>& layer, size_t k, int32_t l) {
    const int32_t v = std::atomic_ref<const int32_t>(layer[k]).load(std::memory_order_relaxed);
    return v >= 0 && v < l;
}

// Fronts of at least this many cells are expanded by two threads.
inline constexpr size_t kMinFrontForThreads = 8192;

// Grows BFS layers from the cells of layer 0 (`front`, with layer[i] == 0; every other cell -1)
// until no cell is reached, in one pass per layer over the compacted front: each front cell
// claims its unreached neighbours (layer[j] from -1 to the new layer, an atomic exchange, so a
// cell is claimed once even on two threads) and `value(j, p, layer)` computes and stores the
// claimed cell's result at once. `value` must read only cells of earlier layers
// (0 <= layer[k] < the layer it is given) and write only cell j: then no cell's result depends
// on the order of the front or on the threads, and the next front is the claimed cells in any
// order. Returns the number of layers after 0.
template <typename Value>
int32_t growLayers(const Box& b, std::vector<uint32_t> front, std::vector<int32_t>& layer, Value&& value) {
    const size_t row = size_t(b.size.x), slice = row * size_t(b.size.y);
    const int32_t offsets[6] = {-1, 1, -int32_t(row), int32_t(row), -int32_t(slice), int32_t(slice)};
    auto expand = [&](const uint32_t* first, const uint32_t* last, int32_t l, std::vector<uint32_t>& out) {
        for (const uint32_t* f = first; f != last; ++f) {
            const glm::ivec3 p = coordinates(b, *f);
            const bool inside[6] = {p.x > 0, p.x + 1 < b.size.x, p.y > 0, p.y + 1 < b.size.y, p.z > 0, p.z + 1 < b.size.z};
            for (int32_t n = 0; n < 6; ++n) {
                if (!inside[n]) continue;
                const uint32_t j = uint32_t(int64_t(*f) + offsets[n]);
                std::atomic_ref<int32_t> claim(layer[j]);
                if (claim.load(std::memory_order_relaxed) != -1) continue;
                int32_t expected = -1;
                if (!claim.compare_exchange_strong(expected, l, std::memory_order_relaxed)) continue;
                glm::ivec3 q = p;
                q[n / 2] += (n & 1) ? 1 : -1;
                value(size_t(j), q, l);
                out.push_back(j);
            }
        }
    };
    int32_t l = 0;
    std::vector<uint32_t> next, second;
    while (!front.empty()) {
        ++l;
        next.clear();
        if (front.size() < kMinFrontForThreads) {
            expand(front.data(), front.data() + front.size(), l, next);
        } else {
            second.clear();
            const uint32_t* mid = front.data() + front.size() / 2;
            std::exception_ptr failed;
            std::thread other([&] {
                try {
                    expand(front.data(), mid, l, second);
                } catch (...) {
                    failed = std::current_exception();
                }
            });
            try {
                expand(mid, front.data() + front.size(), l, next);
            } catch (...) {
                other.join();
                throw;
            }
            other.join();
            if (failed) std::rethrow_exception(failed);
            next.insert(next.end(), second.begin(), second.end());
        }
        if (next.empty()) return l - 1;
        std::swap(front, next);
    }
    return l == 0 ? 0 : l - 1;
}

} // namespace voxc::curves
