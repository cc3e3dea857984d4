#include "voxc/mesh/MeshQuality.h"

#include "voxc/core/HugePages.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <vector>

namespace voxc {
namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// One use of an undirected edge, stored in the bucket of its smaller vertex.
struct EdgeUse {
    uint32_t larger;
    bool forward; // the triangle runs it from the smaller vertex to the larger
};

} // namespace

MeshQuality measureMeshQuality(const Mesh& mesh) {
    MeshQuality q;
    q.vertices = mesh.positions.size();
    q.triangles = mesh.triangles.size() / 3;
    for (size_t v = 0; v < mesh.positions.size(); ++v)
        if (!finite(mesh.positions[v]) || (v < mesh.normals.size() && !finite(mesh.normals[v]))) ++q.nonFiniteVertices;

    // Edge uses bucketed by their smaller vertex (a counting sort: linear in the mesh size).
    auto validTriangle = [&](size_t t) {
        return mesh.triangles[t] < q.vertices && mesh.triangles[t + 1] < q.vertices && mesh.triangles[t + 2] < q.vertices;
    };
    // Edges join points: a copy made for its normal is the vertex it copies (Mesh::normalSplits).
    const size_t firstCopy = q.vertices - std::min(q.vertices, mesh.normalSplits.size());
    auto point = [&](uint32_t v) { return v >= firstCopy && v < q.vertices ? mesh.normalSplits[v - firstCopy] : v; };
    // The counts, offsets and uses are fresh arrays of tens of MiB for a large mesh: on huge pages,
    // their first touch is not a fault per 4 KiB (which took most of the report at 512^3).
    std::vector<size_t> bucketStart;
    resizeOnHugePages(bucketStart, q.vertices + 1);
    for (size_t t = 0; t + 3 <= mesh.triangles.size(); t += 3) {
        if (!validTriangle(t)) continue;
        for (int k = 0; k < 3; ++k) {
            const uint32_t from = point(mesh.triangles[t + size_t(k)]), to = point(mesh.triangles[t + size_t((k + 1) % 3)]);
            if (from != to) ++bucketStart[std::min(from, to) + 1];
        }
    }
    for (size_t v = 0; v < q.vertices; ++v) bucketStart[v + 1] += bucketStart[v];
    std::vector<EdgeUse> uses;
    resizeOnHugePages(uses, bucketStart[q.vertices]);
    std::vector<size_t> fill;
    resizeOnHugePages(fill, q.vertices);
    std::copy(bucketStart.begin(), bucketStart.end() - 1, fill.begin());

    for (size_t t = 0; t + 3 <= mesh.triangles.size(); t += 3) {
        if (!validTriangle(t)) {
            ++q.badIndexTriangles;
            continue;
        }
        const uint32_t i[3] = {point(mesh.triangles[t]), point(mesh.triangles[t + 1]), point(mesh.triangles[t + 2])};
        if (i[0] == i[1] || i[1] == i[2] || i[0] == i[2]) {
            ++q.repeatedIndexTriangles;
        } else {
            const glm::vec3 &a = mesh.positions[i[0]], &b = mesh.positions[i[1]], &c = mesh.positions[i[2]];
            if (glm::cross(b - a, c - a) == glm::vec3(0.0f)) ++q.zeroAreaTriangles;
            const glm::dvec3 da(a), db(b), dc(c);
            q.signedVolume += glm::dot(da, glm::cross(db, dc)) / 6.0;
        }
        for (int k = 0; k < 3; ++k) {
            const uint32_t from = i[k], to = i[(k + 1) % 3];
            if (from == to) continue;
            uses[fill[std::min(from, to)]++] = {std::max(from, to), from < to};
        }
    }
    for (size_t v = 0; v < q.vertices; ++v) {
        const auto first = uses.begin() + std::ptrdiff_t(bucketStart[v]), last = uses.begin() + std::ptrdiff_t(bucketStart[v + 1]);
        std::sort(first, last, [](const EdgeUse& a, const EdgeUse& b) { return a.larger < b.larger; });
        for (auto run = first; run != last;) {
            auto end = run;
            size_t forward = 0;
            for (; end != last && end->larger == run->larger; ++end) forward += end->forward;
            const size_t total = size_t(end - run);
            if (total == 1) ++q.boundaryEdges;
            if (total > 2) ++q.nonManifoldEdges;
            if (total == 2 && forward != 1) ++q.misorientedEdges;
            run = end;
        }
    }
    return q;
}

std::string describeMeshQuality(const MeshQuality& q) {
    std::string text = fmt::format("{} vertices, {} triangles, {} boundary edges, {} non-manifold edges, {} zero-area triangles",
                                   q.vertices, q.triangles, q.boundaryEdges, q.nonManifoldEdges, q.zeroAreaTriangles);
    if (q.misorientedEdges) text += fmt::format(", {} misoriented edges", q.misorientedEdges);
    if (q.repeatedIndexTriangles) text += fmt::format(", {} triangles with a repeated vertex", q.repeatedIndexTriangles);
    if (q.badIndexTriangles) text += fmt::format(", {} triangles with an index out of range", q.badIndexTriangles);
    if (q.nonFiniteVertices) text += fmt::format(", {} non-finite vertices", q.nonFiniteVertices);
    return text;
}

} // namespace voxc
