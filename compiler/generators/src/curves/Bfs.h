#pragma once
// BFS helpers shared by the layer-by-layer propagations (normal fill, material, surface): a
// layer reads only cells set in earlier layers, so the order within a layer never matters.
#include "Parallel.h"

#include "voxc/generators/curves/Grid.h"
#include "voxc/generators/curves/Propagate.h"

#include "voxc/core/Errors.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>

namespace voxc::curves {

inline glm::ivec3 coordinates(const Box& b, size_t i) {
    // 32-bit divisions (a box holds < 2^32 cells): a third of the 64-bit ones' cost.
    const uint32_t index = uint32_t(i), nx = uint32_t(b.size.x), ny = uint32_t(b.size.y);
    const uint32_t row = index / nx;
    return {int32_t(index - row * nx), int32_t(row % ny), int32_t(row / ny)};
}

// coordinates() for many cells of one box, with multiplications instead of divisions: for 32-bit
// n and d > 1, n / d = (ceil(2^64 / d) * n) >> 64 exactly (Lemire, Kaser and Kurz, "Faster
// remainder by direct computation", 2019), so the same coordinates.
class CellCoordinates {
public:
    explicit CellCoordinates(const Box& b)
        : nx_(uint32_t(b.size.x)), ny_(uint32_t(b.size.y)), mx_(inverse(nx_)), my_(inverse(ny_)) {}
    glm::ivec3 operator()(size_t i) const {
        const uint32_t index = uint32_t(i);
        const uint32_t row = divide(index, nx_, mx_), z = divide(row, ny_, my_);
        return {int32_t(index - row * nx_), int32_t(row - z * ny_), int32_t(z)};
    }

private:
    static uint64_t inverse(uint32_t d) { return d > 1 ? UINT64_MAX / d + 1 : 0; }
    static uint32_t divide(uint32_t n, uint32_t d, uint64_t inverse) {
#ifdef __SIZEOF_INT128__
        return d > 1 ? uint32_t((static_cast<unsigned __int128>(inverse) * n) >> 64) : n;
#else
        return n / d;
#endif
    }
    uint32_t nx_, ny_;
    uint64_t mx_, my_;
};

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
inline bool setBefore(const std::vector<FrontLayer>& layer, size_t k, int32_t l) {
    const int32_t v = layer[k];
    return v >= 0 && v < l;
}

// The face neighbours of cell p (coordinates q) in neighbour order, p itself where one is outside
// the box, and as bit n of the returned mask whether neighbour n was set in a layer before `l`,
// p's own layer. Once growLayers values cells every cell has a layer >= 0, so setBefore is
// layer < l, and p's own layer l never counts: the mask needs no branch per neighbour.
inline uint32_t neighboursSetBefore(const Box& b, const std::vector<FrontLayer>& layer, size_t p, glm::ivec3 q, int32_t l,
                                    size_t (&neighbour)[6]) {
    const size_t row = size_t(b.size.x), slice = row * size_t(b.size.y);
    neighbour[0] = q.x > 0 ? p - 1 : p;
    neighbour[1] = q.x + 1 < b.size.x ? p + 1 : p;
    neighbour[2] = q.y > 0 ? p - row : p;
    neighbour[3] = q.y + 1 < b.size.y ? p + row : p;
    neighbour[4] = q.z > 0 ? p - slice : p;
    neighbour[5] = q.z + 1 < b.size.z ? p + slice : p;
    uint32_t before = 0;
    for (int32_t n = 0; n < 6; ++n) before |= uint32_t(layer[neighbour[n]] < l) << n;
    return before;
}

// The fronts value the cells in bands of this many slices (growLayers).
inline constexpr int32_t kBandSlices = 8;

// growLayers' scratch, one entry per cell: the cell's offset in its group of slices (growLayers),
// in 16 bits where a slice holds at most kNarrowOrderSliceCells cells, else 32. A group holds one
// slice, or more only where the layers outnumber a slice's cells (groupSlices * slice < layers + 1
// + slice <= 16,384 + 32,768), so its offsets fit 16 bits: the fronts' largest scratch is half
// the size (16 MiB each at 256x128x256), and is fresh memory the kernel clears (HeapReuse.h).
struct FrontOrder {
    static constexpr size_t kNarrowOrderSliceCells = size_t(1) << 15;
    std::vector<uint16_t> narrow;
    std::vector<uint32_t> wide;

    static bool fitsNarrow(const Box& b) { return size_t(b.size.x) * size_t(b.size.y) <= kNarrowOrderSliceCells; }
    void reserve(const Box& b) {
        if (fitsNarrow(b)) narrow.reserve(b.cellCount());
        else wide.reserve(b.cellCount());
    }
    void resize(const Box& b) {
        if (fitsNarrow(b)) narrow.resize(b.cellCount());
        else wide.resize(b.cellCount());
    }
};

// growLayers' second half: lists the cells of each (layer, group) pair by a counting sort, each
// as its offset in its group (an Index; the group's cells fit it), then values them band by band.
template <typename Index, typename Value>
void valueInBands(const Box& b, const std::vector<FrontLayer>& layer, int32_t layers, int32_t groupSlices,
                  std::vector<Index>& order, Value& value) {
    const int32_t nz = b.size.z;
    const size_t slice = size_t(b.size.x) * size_t(b.size.y), groupCells = size_t(groupSlices) * slice;
    if (groupCells - 1 > size_t(std::numeric_limits<Index>::max()))
        throw InternalError("curves: a front's slice group past its order's index");
    const int32_t groups = (nz + groupSlices - 1) / groupSlices;
    std::vector<uint32_t> start(size_t(layers + 1) * size_t(groups) + 1, 0);
    auto bucket = [&](size_t i, int32_t z) { return size_t(layer[i]) * size_t(groups) + size_t(z / groupSlices); };
    for (int32_t z = 0; z < nz; ++z)
        for (size_t i = size_t(z) * slice, end = i + slice; i < end; ++i) ++start[bucket(i, z) + 1];
    for (size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    const CellCoordinates cellCoordinates(b);
    for (int32_t z = 0; z < nz; ++z) {
        const size_t group = size_t(z / groupSlices) * groupCells;
        for (size_t i = size_t(z) * slice, end = i + slice; i < end; ++i) order[fill[bucket(i, z)]++] = Index(i - group);
    }
    // Bands of s = g + l over the layers after 0 (s from 1 to layers + groups - 1).
    for (int32_t s0 = 1; s0 < layers + groups; s0 += kBandSlices)
        for (int32_t l = std::max(1, s0 - groups + 1); l <= layers && l < s0 + kBandSlices; ++l)
            for (int32_t g = std::max(0, s0 - l), g1 = std::min(groups, s0 + kBandSlices - l); g < g1; ++g) {
                const size_t k = size_t(l) * size_t(groups) + size_t(g), group = size_t(g) * groupCells;
                for (uint32_t c = start[k]; c != start[k + 1]; ++c) {
                    const size_t i = group + order[c];
                    value(i, cellCoordinates(i), l);
                }
            }
}

// Grows BFS layers from the cells of layer 0 (layer[i] == 0; every other cell -1) and calls
// `value(j, p, layer)` once for every other cell j (p its coordinates) to compute and store its
// result. `value` must read only cells of earlier layers (0 <= layer[k] < the layer it is given)
// and write only cell j: then no cell's result depends on the order of the calls as long as every
// neighbour of an earlier layer comes first. The box has no obstacles, so a cell's BFS layer is
// its city-block distance to the nearest cell of layer 0 (three separable passes along x, y and z,
// each forwards then backwards, give every layer at once), and a face neighbour's layer differs
// from the cell's by at most 1: a cell of layer l in slice z reads cells of layer l - 1 in slices
// z - 1 .. z + 1, whose s = z + l - 1 + (-1, 0 or 1) is at most the cell's s = z + l. So the cells are valued in bands of
// kBandSlices values of s, within a band layer by layer, within a layer slice by slice in index
// order (a counting sort lists each (layer, slice) pair's cells in `order`): the cells of consecutive layers
// a band visits lie next to each other, so the fronts read what the layer before left in cache
// (valuing each whole layer in turn read its cells' neighbours from memory, as a layer spans the
// box). `order` is sized by the caller (FrontOrder::resize). Single-threaded: the host runs its
// two fronts side by side (Fronts.h). Returns the number of layers after 0.
template <typename Value>
int32_t growLayers(const Box& b, std::vector<FrontLayer>& layer, FrontOrder& order, Value&& value) {
    if (std::find(layer.begin(), layer.end(), FrontLayer(0)) == layer.end()) return 0; // no cell to grow from
    const int32_t nx = b.size.x, ny = b.size.y, nz = b.size.z;
    const size_t row = size_t(nx), slice = row * size_t(ny);
    // Past every city-block distance in the box (at most nx + ny + nz - 3), and kFar + 1 still a
    // FrontLayer; Limits' 4096 cells per axis keep every box far inside it.
    constexpr int32_t kFar = 1 << 14;
    if (int64_t(nx) + ny + nz - 3 >= kFar) throw InternalError("curves: a front's layers past 16 bits");
    for (FrontLayer& v : layer) v = v == 0 ? FrontLayer(0) : FrontLayer(kFar);
    // min(own, neighbour + 1) in 16 bits (the sum is at most kFar + 1).
    auto closer = [](FrontLayer own, FrontLayer neighbour) { return FrontLayer(std::min<int32_t>(own, neighbour + 1)); };
    forTwoSlabs(nz, 2, [&](int32_t z0, int32_t z1) {
        for (int32_t z = z0; z < z1; ++z) {
            FrontLayer* s = layer.data() + size_t(z) * slice;
            for (int32_t y = 0; y < ny; ++y) {
                FrontLayer* r = s + size_t(y) * row;
                for (int32_t x = 1; x < nx; ++x) r[x] = closer(r[x], r[x - 1]);
                for (int32_t x = nx - 1; x-- > 0;) r[x] = closer(r[x], r[x + 1]);
            }
            for (int32_t y = 1; y < ny; ++y)
                for (size_t x = 0; x < row; ++x) s[size_t(y) * row + x] = closer(s[size_t(y) * row + x], s[size_t(y - 1) * row + x]);
            for (int32_t y = ny - 1; y-- > 0;)
                for (size_t x = 0; x < row; ++x) s[size_t(y) * row + x] = closer(s[size_t(y) * row + x], s[size_t(y + 1) * row + x]);
        }
    });
    forTwoSlabs(ny, 2, [&](int32_t y0, int32_t y1) {
        for (int32_t y = y0; y < y1; ++y) {
            for (int32_t z = 1; z < nz; ++z) {
                FrontLayer* r = layer.data() + size_t(z) * slice + size_t(y) * row;
                for (size_t x = 0; x < row; ++x) r[x] = closer(r[x], r[x - slice]);
            }
            for (int32_t z = nz - 1; z-- > 0;) {
                FrontLayer* r = layer.data() + size_t(z) * slice + size_t(y) * row;
                for (size_t x = 0; x < row; ++x) r[x] = closer(r[x], r[x + slice]);
            }
        }
    });
    // The cells of layer l in slice group g (groupSlices slices each: 1 unless the (layer, slice)
    // pairs outnumber the cells, as in a long thin box), in index order, are valued together. A
    // face neighbour's group differs by at most 1 too.
    int32_t layers = 0;
    for (FrontLayer v : layer) layers = std::max<int32_t>(layers, v);
    const uint64_t pairs = uint64_t(layers + 1) * uint64_t(nz);
    const int32_t groupSlices = int32_t(std::max<uint64_t>(1, (pairs + b.cellCount() - 1) / b.cellCount()));
    if (FrontOrder::fitsNarrow(b)) valueInBands(b, layer, layers, groupSlices, order.narrow, value);
    else valueInBands(b, layer, layers, groupSlices, order.wide, value);
    return layers;
}

} // namespace voxc::curves
