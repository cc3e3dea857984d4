#include "voxc/generators/curves/Propagate.h"

#include "Bfs.h"
#include "Fronts.h"
#include "Parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace voxc::curves {

SurfaceFront prepareSurface(const Constraints& cs, Field3* constraintSurface) {
    const size_t cells = cs.box.cellCount();
    SurfaceFront front;
    front.field.distance.box = cs.box;
    if (constraintSurface) front.field.distance.values = std::move(constraintSurface->values);
    else front.field.distance.values.reserve(cells);
    front.field.layer.reserve(cells);
    front.order.reserve(cs.box);
    return front;
}

SurfaceField propagateSurface(const Constraints& cs, const Field3& nx, const Field3& ny, const Field3& nz,
                              PropagateRule rule) {
    SurfaceFront front = prepareSurface(cs, nullptr);
    growSurface(cs, nx, ny, nz, rule, front);
    return std::move(front.field);
}

void growSurface(const Constraints& cs, const Field3& nx, const Field3& ny, const Field3& nz, PropagateRule rule,
                 SurfaceFront& front) {
    const Box& b = cs.box;
    SurfaceField& out = front.field;
    // Filled here, in the storage prepareSurface reserved (no reallocation), so the first
    // touches of its pages run beside the other front's.
    const size_t cells = b.cellCount();
    constexpr float kAir = std::numeric_limits<float>::infinity();
    // The constraints' own values where prepareSurface took them: kept on Omega_S, +inf elsewhere.
    const bool taken = out.distance.values.size() == cells;
    if (!taken) out.distance.values.resize(cells, kAir);
    out.layer.resize(cells, -1);
    front.order.resize(b);
    for (size_t i = 0; i < cells; ++i)
        if (cs.flags[i] & kInSurface) {
            out.layer[i] = 0;
            if (!taken) out.distance.values[i] = cs.surface.values[i];
        } else if (taken) {
            out.distance.values[i] = kAir;
        }
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

namespace {

// ((a + 2 b) + c) / 4 of three rows into out: the filter's expression, elementwise.
void filterRows(const float* a, const float* b, const float* c, size_t n, float* out) {
    for (size_t x = 0; x < n; ++x) out[x] = ((a[x] + 2.0f * b[x]) + c[x]) * 0.25f;
}

// One [1,2,1]/4 pass along axis 1 (y) or 2 (z) over `count` lines of `n` floats `stride` apart
// (clamped at the ends), in place: each line's new values go to a scratch line and replace it
// once the line after it has read it; `previous` keeps the line before as it was.
void filterLines(float* first, size_t n, size_t stride, int32_t count, std::vector<float>& previous,
                 std::vector<float>& next) {
    std::copy(first, first + n, previous.begin());
    for (int32_t k = 0; k < count; ++k) {
        float* line = first + size_t(k) * stride;
        const float* after = k + 1 < count ? line + stride : line;
        filterRows(previous.data(), line, after, n, next.data());
        std::copy(line, line + n, previous.begin());
        std::copy(next.begin(), next.end(), line);
    }
}

} // namespace

Field3 smoothBinomial(const Field3& field, int32_t passes) {
    // In place on one copy of the field, line by line with a scratch line (the values each cell
    // reads are those of the axis pass before, as with a second field to ping-pong); slices (x, y
    // passes) or rows (z pass) split between two threads, each cell written once per pass.
    const Box& b = field.box;
    Field3 out = field;
    const size_t nx = size_t(b.size.x), slice = nx * size_t(b.size.y);
    for (int32_t pass = 0; pass < passes; ++pass) {
        forTwoSlabs(b.size.z, 2, [&](int32_t z0, int32_t z1) {
            std::vector<float> previous(nx), next(nx);
            for (int32_t z = z0; z < z1; ++z) {
                float* s = out.values.data() + size_t(z) * slice;
                for (int32_t y = 0; y < b.size.y; ++y) {
                    float* r = s + size_t(y) * nx;
                    float before = r[0];
                    for (size_t x = 0; x < nx; ++x) {
                        const float centre = r[x], after = r[std::min(x + 1, nx - 1)];
                        r[x] = ((before + 2.0f * centre) + after) * 0.25f;
                        before = centre;
                    }
                }
                filterLines(s, nx, nx, b.size.y, previous, next);
            }
        });
        forTwoSlabs(b.size.y, 2, [&](int32_t y0, int32_t y1) {
            const size_t n = size_t(y1 - y0) * nx;
            std::vector<float> previous(n), next(n);
            filterLines(out.values.data() + size_t(y0) * nx, n, slice, b.size.z, previous, next);
        });
    }
    return out;
}

} // namespace voxc::curves
