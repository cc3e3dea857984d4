#include "voxc/edit/Pick.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace voxc {

namespace {

constexpr double kStep = 0.125;
constexpr int kBisections = 50; // 1/8 voxel / 2^50: below any float spacing of the grid

float sampleAt(const ChunkedGrid& grid, glm::ivec3 world) {
    const glm::ivec3 local = world - grid.layout().gridOrigin;
    if (glm::any(glm::lessThan(local, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(local, grid.layout().gridSize)))
        return 0.0f;
    const float d = grid.at(local);
    return std::isfinite(d) ? d : 0.0f;
}

} // namespace

double sampleField(const ChunkedGrid& grid, glm::dvec3 p) {
    const glm::dvec3 base = glm::floor(p);
    const glm::dvec3 f = p - base;
    const glm::ivec3 cell(base);
    double value = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 offset(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        const double weight = (offset.x ? f.x : 1.0 - f.x) * (offset.y ? f.y : 1.0 - f.y) * (offset.z ? f.z : 1.0 - f.z);
        if (weight != 0.0) value += weight * sampleAt(grid, cell + offset);
    }
    return value;
}

std::optional<PickHit> pick(const ChunkedGrid& grid, float iso, glm::vec3 origin, glm::vec3 direction, float maxDistance) {
    const glm::dvec3 o(origin);
    glm::dvec3 dir(direction);
    const double length = glm::length(dir);
    if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(o.x + o.y + o.z)) return std::nullopt;
    dir /= length;
    const auto inSolid = [&](double t) { return sampleField(grid, o + t * dir) > double(iso); };
    if (inSolid(0.0)) return PickHit{0.0f, origin, true};

    // Clip to the box where the field can be solid: samples inside the grid and the cells
    // around them, [origin - 1, origin + size].
    const glm::dvec3 low = glm::dvec3(grid.layout().gridOrigin) - 1.0;
    const glm::dvec3 high = glm::dvec3(grid.layout().gridOrigin + grid.layout().gridSize);
    double enter = 0.0, leave = std::min(double(maxDistance), 1e30);
    for (int axis = 0; axis < 3; ++axis) {
        if (dir[axis] == 0.0) {
            if (o[axis] < low[axis] || o[axis] > high[axis]) return std::nullopt;
            continue;
        }
        double a = (low[axis] - o[axis]) / dir[axis], b = (high[axis] - o[axis]) / dir[axis];
        if (a > b) std::swap(a, b);
        enter = std::max(enter, a);
        leave = std::min(leave, b);
    }
    if (enter > leave) return std::nullopt;

    double previous = enter;
    for (double t = enter; previous < leave; t = std::min(t + kStep, leave)) {
        if (inSolid(t)) {
            double air = previous, solid = t;
            for (int i = 0; i < kBisections && air < solid; ++i) {
                const double middle = 0.5 * (air + solid);
                (inSolid(middle) ? solid : air) = middle;
            }
            // The crossing lies between the last air and solid parameters, which now agree to
            // far below a float's resolution.
            const double hit = 0.5 * (air + solid);
            return PickHit{float(hit), glm::vec3(o + hit * dir), false};
        }
        if (t >= leave) break;
        previous = t;
    }
    return std::nullopt;
}

} // namespace voxc
