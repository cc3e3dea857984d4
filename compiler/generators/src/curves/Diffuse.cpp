#include "voxc/generators/curves/Diffuse.h"

#include "Bfs.h"
#include "Fronts.h"
#include "Parallel.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace voxc::curves {
namespace {

float lengthOf(float x, float y, float z) { return std::sqrt((x * x + y * y) + z * z); }

// normalizeField runs on two threads from this many cells (a smaller field's pass takes less
// than starting a thread).
constexpr size_t kMinCellsToNormalizeOnTwoThreads = size_t(1) << 18;

} // namespace

float peronaMalikG(float x, float k) {
    const float q = x / k;
    return 1.0f / (1.0f + q * q);
}

void normalizeField(const Field3& x, const Field3& y, const Field3& z, Field3& outX, Field3& outY, Field3& outZ) {
    for (Field3* out : {&outX, &outY, &outZ}) {
        out->box = x.box;
        out->values.resize(x.values.size()); // every value is written below
    }
    // Pointwise, so two threads (half the cells each) give the same bits.
    auto normalize = [&](size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            const float length = lengthOf(x.values[i], y.values[i], z.values[i]);
            if (!(length >= 1e-6f)) {
                outX.values[i] = outY.values[i] = outZ.values[i] = 0.0f;
                continue;
            }
            outX.values[i] = x.values[i] / length;
            outY.values[i] = y.values[i] / length;
            outZ.values[i] = z.values[i] / length;
        }
    };
    const size_t cells = x.values.size();
    if (cells < kMinCellsToNormalizeOnTwoThreads) return normalize(0, cells);
    bothOf([&] { normalize(0, cells / 2); }, [&] { normalize(cells / 2, cells); });
}

NormalField peronaMalikNormals(const Constraints& cs, float k, uint32_t sweeps, const Limits&) {
    NormalField n = peronaMalikFill(cs);
    peronaMalikSweeps(cs, n, k, sweeps);
    return n;
}

NormalField peronaMalikFill(const Constraints& cs) {
    const Box& b = cs.box;
    NormalField n{cs.normalX, cs.normalY, cs.normalZ, std::vector<uint8_t>(b.cellCount(), 0)};
    std::vector<size_t> front;
    for (size_t i = 0; i < n.set.size(); ++i)
        if (cs.flags[i] & kInNormals) n.set[i] = 1, front.push_back(i);

    // (a) Fill: a layer reads only cells set in earlier layers; every set normal is unit, so
    // the neighbour sum is of unit vectors.
    std::vector<int32_t> stamp(b.cellCount(), -1);
    for (int32_t layer = 1; !front.empty(); ++layer) {
        std::vector<size_t> reached;
        for (size_t i : nextLayer(b, front, n.set, stamp, layer)) {
            const glm::ivec3 p = coordinates(b, i);
            float sx = 0.0f, sy = 0.0f, sz = 0.0f;
            for (const auto& d : kNeighbourOffsets) {
                if (!b.contains(p.x + d[0], p.y + d[1], p.z + d[2])) continue;
                const size_t j = b.index(p.x + d[0], p.y + d[1], p.z + d[2]);
                if (!n.set[j]) continue;
                sx += n.x.values[j], sy += n.y.values[j], sz += n.z.values[j];
            }
            const float length = lengthOf(sx, sy, sz);
            if (!(length >= 1e-6f)) continue;
            n.x.values[i] = sx / length, n.y.values[i] = sy / length, n.z.values[i] = sz / length;
            reached.push_back(i);
        }
        for (size_t i : reached) n.set[i] = 1;
        front = std::move(reached);
    }
    return n;
}

void peronaMalikSweeps(const Constraints& cs, NormalField& n, float k, uint32_t sweeps) {
    const Box& b = cs.box;
    // Jacobi sweeps, ping-pong: N_i + (sum_j c_ij (N_j - N_i)) / 6 over set in-box neighbours.
    // Cells a sweep skips never change, so both buffers hold them from the start.
    Field3 ux(b), uy(b), uz(b);
    NormalField next = n;
    for (uint32_t s = 0; s < sweeps; ++s) {
        normalizeField(n.x, n.y, n.z, ux, uy, uz);
        for (int32_t z = 0; z < b.size.z; ++z)
            for (int32_t y = 0; y < b.size.y; ++y)
                for (int32_t x = 0; x < b.size.x; ++x) {
                    const size_t i = b.index(x, y, z);
                    if (!n.set[i] || (cs.flags[i] & kInNormals)) continue;
                    float ax = 0.0f, ay = 0.0f, az = 0.0f;
                    for (const auto& d : kNeighbourOffsets) {
                        if (!b.contains(x + d[0], y + d[1], z + d[2])) continue;
                        const size_t j = b.index(x + d[0], y + d[1], z + d[2]);
                        if (!n.set[j]) continue;
                        const float dot = (ux.values[i] * ux.values[j] + uy.values[i] * uy.values[j]) + uz.values[i] * uz.values[j];
                        const float c = peronaMalikG(std::clamp((1.0f - dot) * 0.5f, 0.0f, 1.0f), k);
                        ax += c * (n.x.values[j] - n.x.values[i]);
                        ay += c * (n.y.values[j] - n.y.values[i]);
                        az += c * (n.z.values[j] - n.z.values[i]);
                    }
                    next.x.values[i] = n.x.values[i] + ax / 6.0f;
                    next.y.values[i] = n.y.values[i] + ay / 6.0f;
                    next.z.values[i] = n.z.values[i] + az / 6.0f;
                }
        std::swap(n, next);
    }
}

MaterialFront prepareMaterial(const Constraints& cs, std::vector<uint16_t>* constraintMaterial) {
    const size_t cells = cs.box.cellCount();
    MaterialFront front;
    if (constraintMaterial) front.field.material = std::move(*constraintMaterial);
    else front.field.material.reserve(cells);
    front.field.confidence.box = cs.box;
    front.field.confidence.values.reserve(cells);
    front.field.assigned.reserve(cells);
    front.layer.reserve(cells);
    front.order.reserve(cs.box);
    return front;
}

MaterialField propagateMaterial(const Constraints& cs) {
    MaterialFront front = prepareMaterial(cs, nullptr);
    growMaterial(cs, front);
    return std::move(front.field);
}

void growMaterial(const Constraints& cs, MaterialFront& front) {
    const Box& b = cs.box;
    MaterialField& out = front.field;
    // Filled here, in the storage prepareMaterial reserved (no reallocation), so the first
    // touches of its pages run beside the other front's.
    const size_t cells = b.cellCount();
    // The constraints' own ids where prepareMaterial took them: kept on Omega_R, 0 elsewhere.
    const bool taken = out.material.size() == cells;
    if (!taken) out.material.resize(cells, 0);
    out.confidence.values.resize(cells, 0.0f);
    out.assigned.resize(cells, 0);
    front.layer.resize(cells, -1);
    front.order.resize(b);
    for (size_t i = 0; i < cells; ++i)
        if (cs.flags[i] & kInParams) {
            out.assigned[i] = 1, out.confidence.values[i] = 1.0f;
            if (!taken) out.material[i] = cs.material[i];
            front.layer[i] = 0;
        } else if (taken) {
            out.material[i] = 0;
        }
    const std::vector<FrontLayer>& layer = front.layer;
    out.layers = growLayers(b, front.layer, front.order, [&](size_t p, glm::ivec3 q, int32_t l) {
        size_t neighbour[6];
        const uint32_t before = neighboursSetBefore(b, layer, p, q, l, neighbour);
        out.assigned[p] = 1;
        // Mostly every neighbour set before has the same material: then its W_m is the total (the
        // same sums from 0 in the same order), so it is m* and the confidence total / total = 1
        // (a total of confidences >= 1/6 is finite and > 0). A cell of layer l >= 1 has a
        // neighbour of layer l - 1, so `before` is never 0 (the bit 5 or'ed in keeps the index in
        // range regardless).
        const uint16_t first = out.material[neighbour[std::countr_zero(before | 0x20u)]];
        bool same = true;
        for (int32_t n = 0; n < 6; ++n) same &= !((before >> n) & 1) || out.material[neighbour[n]] == first;
        if (same) {
            out.material[p] = first;
            out.confidence.values[p] = 1.0f;
            return;
        }
        uint16_t ids[6] = {};
        float weights[6] = {};
        int32_t distinct = 0;
        float total = 0.0f;
        for (uint32_t set = before; set != 0; set &= set - 1) {
            const size_t j = neighbour[std::countr_zero(set)];
            const float conf = out.confidence.values[j];
            total += conf;
            int32_t slot = 0;
            while (slot < distinct && ids[slot] != out.material[j]) ++slot;
            if (slot == distinct) ids[distinct] = out.material[j], weights[distinct++] = 0.0f;
            weights[slot] += conf;
        }
        int32_t best = 0;
        for (int32_t s = 1; s < distinct; ++s)
            if (weights[s] > weights[best] || (weights[s] == weights[best] && ids[s] < ids[best])) best = s;
        out.material[p] = ids[best];
        out.confidence.values[p] = weights[best] / total;
    });
}

} // namespace voxc::curves
