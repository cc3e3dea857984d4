#include "voxc/generators/curves/Propagate.h"

#include "Bfs.h"

#include <cmath>
#include <limits>

namespace voxc::curves {

float propagationCandidate(float fromValue, float normalP, float normalX, int32_t sign) {
    const float step = (normalP + normalX) * 0.5f;
    return fromValue + (sign > 0 ? step : -step);
}

SurfaceField propagateSurface(const Constraints& cs, const Field3& nx, const Field3& ny, const Field3& nz,
                              PropagateRule rule) {
    const Box& b = cs.box;
    SurfaceField out{Field3(b, std::numeric_limits<float>::infinity()), std::vector<int32_t>(b.cellCount(), -1), 0};
    std::vector<uint8_t> set(b.cellCount(), 0);
    std::vector<size_t> front;
    for (size_t i = 0; i < set.size(); ++i)
        if (cs.flags[i] & kInSurface) {
            set[i] = 1, out.layer[i] = 0, out.distance.values[i] = cs.surface.values[i];
            front.push_back(i);
        }
    const Field3* normal[3] = {&nx, &ny, &nz};
    std::vector<int32_t> stamp(b.cellCount(), -1);
    for (int32_t layer = 1;; ++layer) {
        const std::vector<size_t> cells = nextLayer(b, front, set, stamp, layer);
        if (cells.empty()) break;
        out.layers = layer;
        std::vector<float> values(cells.size());
        for (size_t c = 0; c < cells.size(); ++c) {
            const size_t p = cells[c];
            const glm::ivec3 q = coordinates(b, p);
            float best = 0.0f;
            bool found = false;
            for (const auto& d : kNeighbourOffsets) {
                if (!b.contains(q.x + d[0], q.y + d[1], q.z + d[2])) continue;
                const size_t x = b.index(q.x + d[0], q.y + d[1], q.z + d[2]);
                if (!set[x]) continue;
                const int32_t axis = d[0] != 0 ? 0 : d[1] != 0 ? 1 : 2;
                const int32_t sign = -(d[0] + d[1] + d[2]); // p - x along the axis
                const float candidate = propagationCandidate(out.distance.values[x], normal[axis]->values[p],
                                                             normal[axis]->values[x], sign);
                const bool better = rule == PropagateRule::SignedMin
                                        ? candidate < best
                                        : std::abs(candidate) < std::abs(best) ||
                                              (std::abs(candidate) == std::abs(best) && candidate < best);
                if (!found || better) best = candidate, found = true;
            }
            values[c] = best;
        }
        for (size_t c = 0; c < cells.size(); ++c) {
            set[cells[c]] = 1;
            out.layer[cells[c]] = layer;
            out.distance.values[cells[c]] = values[c];
        }
        front = cells;
    }
    return out;
}

Field3 smoothBinomial(const Field3& field, int32_t passes) {
    const Box& b = field.box;
    Field3 current = field, next = field;
    for (int32_t pass = 0; pass < passes; ++pass)
        for (int32_t axis = 0; axis < 3; ++axis) {
            for (int32_t z = 0; z < b.size.z; ++z)
                for (int32_t y = 0; y < b.size.y; ++y)
                    for (int32_t x = 0; x < b.size.x; ++x) {
                        glm::ivec3 lo(x, y, z), hi(x, y, z);
                        lo[axis] = std::max(lo[axis] - 1, 0);
                        hi[axis] = std::min(hi[axis] + 1, b.size[axis] - 1);
                        const float a = current.at(lo.x, lo.y, lo.z), c = current.at(hi.x, hi.y, hi.z);
                        next.at(x, y, z) = ((a + 2.0f * current.at(x, y, z)) + c) * 0.25f;
                    }
            std::swap(current, next);
        }
    return current;
}

} // namespace voxc::curves
