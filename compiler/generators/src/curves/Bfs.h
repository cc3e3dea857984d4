#pragma once
// BFS helpers shared by the layer-by-layer propagations (normal fill, material, surface): a
// layer reads only cells set in earlier layers, so the order within a layer never matters.
#include "Parallel.h"

#include "voxc/generators/curves/Grid.h"

#include <algorithm>
#include <atomic>
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

// Whether cell k was set in a layer before `l` (layer[k] in [0, l)); growLayers sets every
// cell's layer before it values any, so the threads only read them.
inline bool setBefore(const std::vector<int32_t>& layer, size_t k, int32_t l) {
    const int32_t v = layer[k];
    return v >= 0 && v < l;
}

// Layers of at least this many cells are valued by two threads, in chunks of kLayerChunk cells.
inline constexpr uint32_t kMinFrontForThreads = 8192, kLayerChunk = 1024;

// Grows BFS layers from the cells of layer 0 (layer[i] == 0; every other cell -1) and calls `value(j, p, layer)` once for every other cell j (p its coordinates) to compute and
// store its result. `value` must read only cells of earlier layers (0 <= layer[k] < the layer it
// is given) and write only cell j: then no cell's result depends on the order a layer's cells are
// visited or on the threads. The box has no obstacles, so a cell's BFS layer is its city-block
// distance to the nearest cell of layer 0: three separable passes (along x, y, z, each forwards
// then backwards) give every layer at once, a counting sort lists each layer's cells in index
// order, and the values run layer by layer over those lists, slice by slice through the box (a
// front grown by claiming neighbours, in the order they were claimed, read its cells nearly at
// random and paid an atomic exchange per cell). Returns the number of layers after 0.
template <typename Value>
int32_t growLayers(const Box& b, std::vector<int32_t>& layer, Value&& value) {
    if (std::find(layer.begin(), layer.end(), 0) == layer.end()) return 0; // no cell to grow from
    const int32_t nx = b.size.x, ny = b.size.y, nz = b.size.z;
    const size_t row = size_t(nx), slice = row * size_t(ny);
    // Past every city-block distance in a box (axes < 2^20 cells each), and far from overflow.
    constexpr int32_t kFar = 1 << 29;
    for (int32_t& v : layer) v = v == 0 ? 0 : kFar;
    forTwoSlabs(nz, 2, [&](int32_t z0, int32_t z1) {
        for (int32_t z = z0; z < z1; ++z) {
            int32_t* s = layer.data() + size_t(z) * slice;
            for (int32_t y = 0; y < ny; ++y) {
                int32_t* r = s + size_t(y) * row;
                for (int32_t x = 1; x < nx; ++x) r[x] = std::min(r[x], r[x - 1] + 1);
                for (int32_t x = nx - 1; x-- > 0;) r[x] = std::min(r[x], r[x + 1] + 1);
            }
            for (int32_t y = 1; y < ny; ++y)
                for (size_t x = 0; x < row; ++x) s[size_t(y) * row + x] = std::min(s[size_t(y) * row + x], s[size_t(y - 1) * row + x] + 1);
            for (int32_t y = ny - 1; y-- > 0;)
                for (size_t x = 0; x < row; ++x) s[size_t(y) * row + x] = std::min(s[size_t(y) * row + x], s[size_t(y + 1) * row + x] + 1);
        }
    });
    forTwoSlabs(ny, 2, [&](int32_t y0, int32_t y1) {
        for (int32_t y = y0; y < y1; ++y) {
            for (int32_t z = 1; z < nz; ++z) {
                int32_t* r = layer.data() + size_t(z) * slice + size_t(y) * row;
                for (size_t x = 0; x < row; ++x) r[x] = std::min(r[x], r[x - slice] + 1);
            }
            for (int32_t z = nz - 1; z-- > 0;) {
                int32_t* r = layer.data() + size_t(z) * slice + size_t(y) * row;
                for (size_t x = 0; x < row; ++x) r[x] = std::min(r[x], r[x + slice] + 1);
            }
        }
    });
    // Each layer's cells in index order: start[l] .. start[l + 1] of `order`.
    int32_t layers = 0;
    for (int32_t v : layer) layers = std::max(layers, v);
    std::vector<uint32_t> start(size_t(layers) + 2, 0);
    for (int32_t v : layer) ++start[size_t(v) + 1];
    for (size_t l = 1; l < start.size(); ++l) start[l] += start[l - 1];
    std::vector<uint32_t> order(layer.size()), fill(start.begin(), start.end() - 1);
    for (size_t i = 0; i < layer.size(); ++i) order[fill[size_t(layer[i])]++] = uint32_t(i);
    auto run = [&](const uint32_t* first, const uint32_t* last, int32_t l) {
        for (const uint32_t* c = first; c != last; ++c) value(size_t(*c), coordinates(b, *c), l);
    };
    // A large layer's cells are taken in chunks from a shared counter by this thread and a helper
    // that lives as long as the growth, whichever comes first: a thread without a core (a loaded
    // machine) then holds a layer up by at most the chunk it took. (Halving every layer between
    // two threads, each started for its layer, made the fronts slower on two loaded cores than on
    // one.) The layer's description is written before its generation is published in `claim`
    // (generation << 32 | the next cell to take); a take is a compare-exchange on that word, so
    // it succeeds only while the layer it read is the current one and unfinished.
    std::atomic<uint64_t> claim{0};
    std::atomic<uint32_t> done{0}, count{0};
    std::atomic<const uint32_t*> cells{nullptr};
    std::atomic<int32_t> current{0};
    std::atomic<bool> stop{false};
    auto help = [&](uint32_t generation) {
        uint64_t word = claim.load(std::memory_order_acquire);
        while (uint32_t(word >> 32) == generation) {
            const uint32_t next = uint32_t(word), n = count.load(std::memory_order_relaxed);
            if (next >= n) return;
            const uint32_t* layerCells = cells.load(std::memory_order_relaxed);
            const int32_t l = current.load(std::memory_order_relaxed);
            const uint32_t taken = std::min(next + kLayerChunk, n);
            if (!claim.compare_exchange_weak(word, (word & ~uint64_t(0xffffffffu)) | taken, std::memory_order_acq_rel,
                                             std::memory_order_acquire))
                continue;
            run(layerCells + next, layerCells + taken, l);
            done.fetch_add(taken - next, std::memory_order_release);
            done.notify_one();
        }
    };
    std::thread helper;
    uint32_t generation = 0;
    for (int32_t l = 1; l <= layers; ++l) {
        const uint32_t* first = order.data() + start[size_t(l)];
        const uint32_t n = start[size_t(l) + 1] - start[size_t(l)];
        if (n < kMinFrontForThreads) {
            run(first, first + n, l);
            continue;
        }
        if (!helper.joinable())
            helper = std::thread([&] {
                for (uint32_t seen = 0;;) {
                    uint64_t word = claim.load(std::memory_order_acquire);
                    while (uint32_t(word >> 32) == seen) {
                        claim.wait(word, std::memory_order_acquire);
                        word = claim.load(std::memory_order_acquire);
                    }
                    if (stop.load(std::memory_order_acquire)) return;
                    seen = uint32_t(word >> 32);
                    help(seen);
                }
            });
        count.store(n, std::memory_order_relaxed);
        cells.store(first, std::memory_order_relaxed);
        current.store(l, std::memory_order_relaxed);
        done.store(0, std::memory_order_relaxed);
        claim.store(uint64_t(++generation) << 32, std::memory_order_release);
        claim.notify_one();
        help(generation);
        for (uint32_t d = done.load(std::memory_order_acquire); d < n; d = done.load(std::memory_order_acquire))
            done.wait(d, std::memory_order_acquire);
    }
    if (helper.joinable()) {
        stop.store(true, std::memory_order_release);
        claim.store(uint64_t(++generation) << 32, std::memory_order_release);
        claim.notify_one();
        helper.join();
    }
    return layers;
}

} // namespace voxc::curves
