#include "voxc/generators/inputs/MeshDistance.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/vector_relational.hpp>
#include <glm/mat4x4.hpp>
#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>

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

// Edges after welding equal positions: how many border one triangle, and more than two; and the
// closed parts (pieces joined through shared vertices, every edge of them bordering exactly two
// triangles) that enclose a negative volume and lie in no positive one's box: inside out.
void surveyTopology(const std::vector<openvdb::Vec3s>& points, const std::vector<openvdb::Vec3I>& triangles,
                    DistanceGrid& grid) {
    std::map<std::array<float, 3>, uint32_t> welded;
    std::vector<uint32_t> id(points.size());
    for (size_t i = 0; i < points.size(); ++i)
        id[i] = welded.emplace(std::array<float, 3>{points[i].x(), points[i].y(), points[i].z()}, uint32_t(welded.size()))
                    .first->second;
    // Parts: a union-find over the welded vertices.
    std::vector<uint32_t> parent(welded.size());
    for (uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
    const auto root = [&](uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> uses;
    for (const openvdb::Vec3I& t : triangles)
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
    for (const openvdb::Vec3I& t : triangles) {
        Part& part = parts[root(id[t[0]])];
        glm::dvec3 p[3];
        for (int k = 0; k < 3; ++k) {
            p[k] = glm::dvec3(points[t[k]].x(), points[t[k]].y(), points[t[k]].z());
            part.lo = glm::min(part.lo, p[k]), part.hi = glm::max(part.hi, p[k]);
        }
        if (!part.hasOrigin) part.origin = p[0], part.hasOrigin = true;
        part.volume += glm::dot(p[0] - part.origin, glm::cross(p[1] - part.origin, p[2] - part.origin));
    }
    for (const auto& [key, part] : parts) {
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
    static std::once_flag initialised;
    std::call_once(initialised, [] { openvdb::initialize(); });
    std::vector<openvdb::Vec3s> points;
    points.reserve(mesh.points.size());
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const glm::dvec3& p : placePoints(mesh, transform)) {
        lo = glm::min(lo, p), hi = glm::max(hi, p);
        points.emplace_back(float(p.x), float(p.y), float(p.z));
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
    std::vector<openvdb::Vec3I> triangles;
    triangles.reserve(mesh.triangles.size());
    for (const glm::uvec3& t : mesh.triangles) triangles.emplace_back(t.x, t.y, t.z);
    surveyTopology(points, triangles, grid);
    // Index space = world voxels: voxel (i, j, k) of the VDB grid is world voxel (i, j, k).
    const openvdb::math::Transform::Ptr identity = openvdb::math::Transform::createLinearTransform(1.0);
    const openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> adapter(points, triangles);
    const openvdb::FloatGrid::Ptr vdb = openvdb::tools::meshToVolume<openvdb::FloatGrid>(adapter, *identity, band, band);
    const openvdb::FloatGrid::ConstAccessor accessor = vdb->getConstAccessor();
    grid.values.resize(size_t(cells));
    size_t at = 0;
    for (int32_t z = 0; z < grid.size.z; ++z)
        for (int32_t y = 0; y < grid.size.y; ++y)
            for (int32_t x = 0; x < grid.size.x; ++x, ++at) {
                const float v = accessor.getValue(openvdb::Coord(grid.min.x + x, grid.min.y + y, grid.min.z + z));
                grid.values[at] = std::clamp(v, -band, band);
            }
    return grid;
}

} // namespace voxc::inputs
