#include "voxc/edit/Pick.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <vector>

namespace voxc {

namespace {

constexpr double kStep = 0.125;
constexpr int kBisections = 50; // 1/8 voxel / 2^50: below any float spacing of the grid
// The refinement (refineOnCrossings) moves a hit by at most this: the trilinear field's own error is
// about a tenth of it, so a larger move means the fit saw something else (another surface).
constexpr double kMaxRefinement = 0.25;

float sampleAt(const ChunkedGrid& grid, glm::ivec3 world) {
    const glm::ivec3 local = world - grid.layout().gridOrigin;
    if (glm::any(glm::lessThan(local, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(local, grid.layout().gridSize)))
        return 0.0f;
    const float d = grid.at(local);
    return std::isfinite(d) ? d : 0.0f;
}

// Solves the 6x6 system by Gaussian elimination with partial pivoting; false when it is singular
// (the crossings do not determine a quadratic: too few, or all on a line).
bool solve6(std::array<std::array<double, 7>, 6>& m) {
    for (int col = 0; col < 6; ++col) {
        int pivot = col;
        for (int row = col + 1; row < 6; ++row)
            if (std::abs(m[row][col]) > std::abs(m[pivot][col])) pivot = row;
        if (std::abs(m[pivot][col]) < 1e-9) return false;
        std::swap(m[col], m[pivot]);
        for (int row = 0; row < 6; ++row) {
            if (row == col) continue;
            const double factor = m[row][col] / m[col][col];
            for (int k = col; k < 7; ++k) m[row][k] -= factor * m[col][k];
        }
    }
    for (int row = 0; row < 6; ++row) m[row][6] /= m[row][row];
    return true;
}

// The trilinear field bends a curved surface by up to h^2 tr(H) / 8 in a cell's middle (three axes'
// interpolation errors add up: 0.027 voxel on a sphere of radius 10), while a grid edge's linear
// crossing, the meshers' vertex, is off by one axis' h^2 / (8 R) at most. So the hit moves onto a
// quadratic height field z = h(x, y), fitted by least squares to the edge crossings of the 4x4x4
// samples around it in a frame whose z is the field's gradient there, where the ray meets it. Kept
// only when the fit is determined, the ray is not tangent to it and the move is under kMaxRefinement.
double refineOnCrossings(const ChunkedGrid& grid, double iso, glm::dvec3 o, glm::dvec3 dir, double t) {
    const glm::dvec3 p = o + t * dir;
    constexpr double kDelta = 1e-3;
    glm::dvec3 gradient;
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 step(0.0);
        step[axis] = kDelta;
        gradient[axis] = sampleField(grid, p + step) - sampleField(grid, p - step);
    }
    if (!(glm::length(gradient) > 0.0)) return t;
    const glm::dvec3 n = glm::normalize(gradient);
    const glm::dvec3 u = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 v = glm::cross(n, u);

    std::array<std::array<double, 7>, 6> normal{}; // the normal equations, right-hand side last
    int crossings = 0;
    const glm::ivec3 first = glm::ivec3(glm::floor(p)) - 1;
    for (int axis = 0; axis < 3; ++axis)
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b)
                for (int c = 0; c < 3; ++c) {
                    glm::ivec3 at = first;
                    at[axis] += c;
                    at[(axis + 1) % 3] += a;
                    at[(axis + 2) % 3] += b;
                    glm::ivec3 next = at;
                    ++next[axis];
                    const double d0 = sampleAt(grid, at), d1 = sampleAt(grid, next);
                    if ((d0 > iso) == (d1 > iso)) continue;
                    glm::dvec3 q(at);
                    q[axis] += (iso - d0) / (d1 - d0);
                    const glm::dvec3 d = q - p;
                    const double x = glm::dot(d, u), y = glm::dot(d, v), z = glm::dot(d, n);
                    if (std::abs(z) > 1.0) continue; // far off the tangent plane: another sheet
                    const std::array<double, 6> row{1.0, x, y, x * x, x * y, y * y};
                    for (int i = 0; i < 6; ++i) {
                        for (int j = 0; j < 6; ++j) normal[i][j] += row[i] * row[j];
                        normal[i][6] += row[i] * z;
                    }
                    ++crossings;
                }
    if (crossings < 6 || !solve6(normal)) return t;
    std::array<double, 6> h;
    for (int i = 0; i < 6; ++i) h[i] = normal[i][6];
    // Along the ray from p, s further: x = s du, y = s dv, z = s dn; z - h(x, y) = 0 is quadratic in s.
    const double du = glm::dot(dir, u), dv = glm::dot(dir, v), dn = glm::dot(dir, n);
    const double qa = -(h[3] * du * du + h[4] * du * dv + h[5] * dv * dv);
    const double qb = dn - h[1] * du - h[2] * dv;
    const double qc = -h[0];
    if (std::abs(qb) < 1e-3) return t; // grazing: the quadratic cannot place the hit
    double s = -qc / qb;
    if (std::abs(qa) > 1e-12) {
        const double discriminant = qb * qb - 4.0 * qa * qc;
        if (discriminant < 0.0) return t;
        const double root = std::sqrt(discriminant);
        // The root nearer the trilinear hit, computed without cancellation.
        const double q = -0.5 * (qb + std::copysign(root, qb));
        s = std::abs(qc / q) < std::abs(q / qa) ? qc / q : q / qa;
    }
    if (!(std::abs(s) <= kMaxRefinement) || t + s < 0.0) return t;
    return t + s;
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
            const double hit = refineOnCrossings(grid, iso, o, dir, 0.5 * (air + solid));
            return PickHit{float(hit), glm::vec3(o + hit * dir), false};
        }
        if (t >= leave) break;
        previous = t;
    }
    return std::nullopt;
}

} // namespace voxc
