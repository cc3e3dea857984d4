#include "voxc/generators/curves/Propagate.h"

#include "Bfs.h"
#include "Fronts.h"

#include <cmath>
#include <limits>

namespace voxc::curves {

float propagationCandidate(float fromValue, float normalP, float normalX, int32_t sign) {
    const float step = (normalP + normalX) * 0.5f;
    return fromValue + (sign > 0 ? step : -step);
}

SurfaceFront prepareSurface(const Constraints& cs) {
    const Box& b = cs.box;
    SurfaceFront front{{Field3(b, std::numeric_limits<float>::infinity()), std::vector<int32_t>(b.cellCount(), -1), 0},
                       std::vector<uint32_t>(b.cellCount())};
    SurfaceField& out = front.field;
    for (size_t i = 0; i < out.layer.size(); ++i)
        if (cs.flags[i] & kInSurface) {
            out.layer[i] = 0, out.distance.values[i] = cs.surface.values[i];
        }
    return front;
}

SurfaceField propagateSurface(const Constraints& cs, const Field3& nx, const Field3& ny, const Field3& nz,
                              PropagateRule rule) {
    SurfaceFront front = prepareSurface(cs);
    growSurface(cs, nx, ny, nz, rule, front);
    return std::move(front.field);
}

void growSurface(const Constraints& cs, const Field3& nx, const Field3& ny, const Field3& nz, PropagateRule rule,
                 SurfaceFront& front) {
    const Box& b = cs.box;
    SurfaceField& out = front.field;
    const Field3* normal[3] = {&nx, &ny, &nz};
    const size_t row = size_t(b.size.x), slice = row * size_t(b.size.y);
    out.layers = growLayers(b, out.layer, front.order, [&](size_t p, glm::ivec3 q, int32_t layer) {
        // Candidates from the neighbours set in earlier layers, in neighbour order.
        const bool inside[6] = {q.x > 0, q.x + 1 < b.size.x, q.y > 0, q.y + 1 < b.size.y, q.z > 0, q.z + 1 < b.size.z};
        const size_t neighbour[6] = {p - 1, p + 1, p - row, p + row, p - slice, p + slice};
        float best = 0.0f;
        bool found = false;
        for (int32_t n = 0; n < 6; ++n) {
            if (!inside[n] || !setBefore(out.layer, neighbour[n], layer)) continue;
            const size_t x = neighbour[n];
            const int32_t axis = n / 2;
            const int32_t sign = (n & 1) ? -1 : 1; // p - x along the axis
            const float candidate = propagationCandidate(out.distance.values[x], normal[axis]->values[p],
                                                         normal[axis]->values[x], sign);
            const bool better = rule == PropagateRule::SignedMin
                                    ? candidate < best
                                    : std::abs(candidate) < std::abs(best) ||
                                          (std::abs(candidate) == std::abs(best) && candidate < best);
            if (!found || better) best = candidate, found = true;
        }
        out.distance.values[p] = best;
    });
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
