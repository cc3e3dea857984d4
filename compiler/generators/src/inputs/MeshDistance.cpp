#include "voxc/generators/inputs/MeshDistance.h"

#include "voxc/vdb/Vdb.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/ext/vector_int3_sized.hpp>
#include <glm/vector_relational.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>

namespace voxc::inputs {

namespace {

constexpr double kMaxCoordinate = 1e7;

glm::dmat4 worldMatrix(const MeshTransform& transform) {
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), transform.translate);
    const glm::dvec3 radians = glm::radians(transform.rotateDegrees);
    m = glm::rotate(m, radians.z, glm::dvec3(0, 0, 1));
    m = glm::rotate(m, radians.y, glm::dvec3(0, 1, 0));
    m = glm::rotate(m, radians.x, glm::dvec3(1, 0, 0));
    return glm::scale(m, glm::dvec3(transform.scale));
}

// Six times the signed volume of (a, b, c, d): positive when d lies on the side of abc its
// counter-clockwise normal points to.
double orient(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
    return glm::dot(b - a, glm::cross(c - a, d - a));
}

// Whether segment pq passes through the inside of triangle abc, strictly (touching is not).
bool segmentCrosses(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& a, const glm::dvec3& b,
                    const glm::dvec3& c) {
    const double dp = orient(a, b, c, p), dq = orient(a, b, c, q);
    if (!(dp * dq < 0.0)) return false;
    const double s1 = orient(p, q, a, b), s2 = orient(p, q, b, c), s3 = orient(p, q, c, a);
    return (s1 > 0.0 && s2 > 0.0 && s3 > 0.0) || (s1 < 0.0 && s2 < 0.0 && s3 < 0.0);
}

// Two triangles that are not coplanar cross iff an edge of one passes through the other.
bool trianglesCross(const std::array<glm::dvec3, 3>& t, const std::array<glm::dvec3, 3>& u) {
    for (int k = 0; k < 3; ++k)
        if (segmentCrosses(t[k], t[(k + 1) % 3], u[0], u[1], u[2]) || segmentCrosses(u[k], u[(k + 1) % 3], t[0], t[1], t[2]))
            return true;
    return false;
}

struct CellHash {
    size_t operator()(const glm::i64vec3& c) const {
        return size_t((uint64_t(c.x) * 0x9E3779B97F4A7C15ull) ^ (uint64_t(c.y) * 0xC2B2AE3D27D4EB4Full) ^
                      (uint64_t(c.z) * 0x165667B19E3779F9ull));
    }
};

// Pairs of triangles sharing no vertex (after welding) that cross each other: the triangles'
// boxes in a spatial hash of cells as wide as the mean triangle's longest box side, and a pair
// whose boxes overlap tested in the one cell that holds the overlap's lowest corner. Bounded: at
// most 32 cell entries per triangle and 64 pair tests per triangle (plus 10^6); past either the
// search stops and what it found so far is reported.
void findCrossings(const std::vector<glm::dvec3>& p, const std::vector<glm::uvec3>& triangles,
                   const std::vector<uint32_t>& id, DistanceGrid& grid) {
    const size_t n = triangles.size();
    if (n < 2) return;
    std::vector<std::array<glm::dvec3, 3>> corners(n);
    std::vector<glm::dvec3> lo(n), hi(n);
    double meanSide = 0.0;
    for (size_t i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) corners[i][size_t(k)] = p[triangles[i][k]];
        lo[i] = glm::min(glm::min(corners[i][0], corners[i][1]), corners[i][2]);
        hi[i] = glm::max(glm::max(corners[i][0], corners[i][1]), corners[i][2]);
        meanSide += std::max({hi[i].x - lo[i].x, hi[i].y - lo[i].y, hi[i].z - lo[i].z}) / double(n);
    }
    const double side = std::max(meanSide, 1e-6);
    const auto cellOf = [&](const glm::dvec3& q) { return glm::i64vec3(glm::floor(q / side)); };
    const uint64_t maxEntries = 32 * uint64_t(n), maxTests = 64 * uint64_t(n) + 1'000'000;
    std::unordered_map<glm::i64vec3, std::vector<uint32_t>, CellHash> cells;
    uint64_t entries = 0, tests = 0;
    for (size_t i = 0; i < n; ++i) {
        const glm::i64vec3 a = cellOf(lo[i]), b = cellOf(hi[i]);
        for (int64_t z = a.z; z <= b.z; ++z)
            for (int64_t y = a.y; y <= b.y; ++y)
                for (int64_t x = a.x; x <= b.x; ++x) {
                    if (++entries > maxEntries) return;
                    cells[glm::i64vec3(x, y, z)].push_back(uint32_t(i));
                }
    }
    for (const auto& [at, members] : cells)
        for (size_t x = 0; x < members.size(); ++x)
            for (size_t y = x + 1; y < members.size(); ++y) {
                const uint32_t i = members[x], j = members[y];
                if (glm::any(glm::lessThan(hi[i], lo[j])) || glm::any(glm::lessThan(hi[j], lo[i]))) continue;
                if (cellOf(glm::max(lo[i], lo[j])) != at) continue; // tested in another cell
                const glm::uvec3 &t = triangles[i], &u = triangles[j];
                bool shared = false;
                for (int k = 0; k < 3; ++k)
                    for (int m = 0; m < 3; ++m) shared = shared || id[t[k]] == id[u[m]];
                if (shared) continue;
                if (++tests > maxTests) return;
                if (!trianglesCross(corners[i], corners[j])) continue;
                const std::pair<uint32_t, uint32_t> pair{std::min(i, j), std::max(i, j)};
                grid.firstCrossing = grid.crossingPairs++ == 0 ? pair : std::min(grid.firstCrossing, pair);
            }
}

// Edges after welding equal positions: how many border one triangle, and more than two; and the
// closed parts (pieces joined through shared vertices, every edge of them bordering exactly two
// triangles) that enclose a negative volume and lie in no positive one's box: inside out.
void surveyTopology(const std::vector<glm::vec3>& points, const std::vector<glm::uvec3>& triangles,
                    DistanceGrid& grid) {
    std::map<std::array<float, 3>, uint32_t> welded;
    std::vector<uint32_t> id(points.size());
    for (size_t i = 0; i < points.size(); ++i)
        id[i] = welded.emplace(std::array<float, 3>{points[i].x, points[i].y, points[i].z}, uint32_t(welded.size()))
                    .first->second;
    // Parts: a union-find over the welded vertices.
    std::vector<uint32_t> parent(welded.size());
    for (uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
    const auto root = [&](uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> uses;
    for (const glm::uvec3& t : triangles)
        for (int k = 0; k < 3; ++k) {
            uint32_t a = id[t[k]], b = id[t[(k + 1) % 3]];
            parent[root(a)] = root(b);
            if (a == b) continue; // a degenerate triangle's collapsed edge
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    struct Part {
        bool closed = true;
        double volume = 0.0; // six times the signed volume, about the part's first vertex
        bool hasOrigin = false;
        glm::dvec3 origin{0.0}, lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
    };
    std::map<uint32_t, Part> parts;
    for (const auto& [edge, count] : uses) {
        grid.openEdges += count == 1;
        grid.nonManifoldEdges += count > 2;
        if (count != 2) parts[root(edge.first)].closed = false;
    }
    std::vector<glm::dvec3> exact(points.size());
    for (size_t i = 0; i < points.size(); ++i) exact[i] = glm::dvec3(points[i]);
    for (const glm::uvec3& t : triangles) {
        Part& part = parts[root(id[t[0]])];
        const glm::dvec3 p[3] = {exact[t[0]], exact[t[1]], exact[t[2]]};
        for (const glm::dvec3& corner : p) part.lo = glm::min(part.lo, corner), part.hi = glm::max(part.hi, corner);
        if (!part.hasOrigin) part.origin = p[0], part.hasOrigin = true;
        part.volume += glm::dot(p[0] - part.origin, glm::cross(p[1] - part.origin, p[2] - part.origin));
    }
    for (const auto& entry : parts) {
        const Part& part = entry.second;
        if (!part.closed || !(part.volume < 0.0)) continue;
        // The inner wall of a hollow, inside an outward part's box, is wound inward on purpose.
        const bool wall = std::any_of(parts.begin(), parts.end(), [&](const auto& other) {
            const Part& o = other.second;
            return o.closed && o.volume > 0.0 && glm::all(glm::lessThanEqual(o.lo, part.lo)) &&
                   glm::all(glm::lessThanEqual(part.hi, o.hi));
        });
        if (wall) continue;
        ++grid.insideOutParts;
        grid.insideOutVolume += -part.volume / 6.0;
    }
    findCrossings(exact, triangles, id, grid);
}

} // namespace

std::vector<glm::dvec3> placePoints(const TriangleMesh& mesh, const MeshTransform& transform) {
    const glm::dmat4 matrix = worldMatrix(transform);
    std::vector<glm::dvec3> placed;
    placed.reserve(mesh.points.size());
    for (size_t i = 0; i < mesh.points.size(); ++i) {
        const glm::dvec3 p = glm::dvec3(matrix * glm::dvec4(mesh.points[i], 1.0));
        for (int a = 0; a < 3; ++a)
            if (!(std::abs(p[a]) <= kMaxCoordinate))
                throw InputError("E0102", fmt::format("vertex {} lies at ({}, {}, {}) once placed, beyond ±{} voxels", i,
                                                      p.x, p.y, p.z, kMaxCoordinate));
        placed.push_back(p);
    }
    return placed;
}

DistanceGrid meshDistances(const TriangleMesh& mesh, const MeshTransform& transform, float band, const Limits& limits) {
    std::vector<glm::vec3> points;
    points.reserve(mesh.points.size());
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const glm::dvec3& p : placePoints(mesh, transform)) {
        lo = glm::min(lo, p), hi = glm::max(hi, p);
        points.emplace_back(p);
    }
    DistanceGrid grid;
    grid.band = band;
    const int32_t margin = int32_t(std::ceil(band)) + 1;
    grid.min = glm::ivec3(glm::floor(lo)) - margin;
    const glm::ivec3 max = glm::ivec3(glm::ceil(hi)) + margin;
    grid.size = max - grid.min + 1;
    const int64_t cells = int64_t(grid.size.x) * grid.size.y * grid.size.z;
    if (cells > limits.maxDistanceCells)
        throw InputError("E0012", fmt::format("the mesh's signed-distance grid would be {} x {} x {} voxels ({} cells), "
                                              "more than the limit of {}; scale it down",
                                              grid.size.x, grid.size.y, grid.size.z, cells, limits.maxDistanceCells));
    surveyTopology(points, mesh.triangles, grid);
    grid.values = vdb::meshSignedDistances(points, mesh.triangles, band, grid.min, grid.size);
    for (float& v : grid.values) v = std::clamp(v, -band, band);
    return grid;
}

} // namespace voxc::inputs
