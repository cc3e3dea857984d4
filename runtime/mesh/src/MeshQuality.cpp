#include "voxc/mesh/MeshQuality.h"

#include <cmath>
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <unordered_map>

namespace voxc {
namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Uses of one undirected edge, counted per direction.
struct EdgeUses {
    uint32_t forward = 0; // from the smaller index to the larger
    uint32_t backward = 0;
};

} // namespace

MeshQuality measureMeshQuality(const Mesh& mesh) {
    MeshQuality q;
    q.vertices = mesh.positions.size();
    q.triangles = mesh.triangles.size() / 3;
    for (size_t v = 0; v < mesh.positions.size(); ++v)
        if (!finite(mesh.positions[v]) || (v < mesh.normals.size() && !finite(mesh.normals[v]))) ++q.nonFiniteVertices;

    std::unordered_map<uint64_t, EdgeUses> edges;
    edges.reserve(mesh.triangles.size());
    for (size_t t = 0; t + 3 <= mesh.triangles.size(); t += 3) {
        const uint32_t i[3] = {mesh.triangles[t], mesh.triangles[t + 1], mesh.triangles[t + 2]};
        if (i[0] >= q.vertices || i[1] >= q.vertices || i[2] >= q.vertices) {
            ++q.badIndexTriangles;
            continue;
        }
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
            EdgeUses& uses = edges[uint64_t(std::min(from, to)) << 32 | std::max(from, to)];
            (from < to ? uses.forward : uses.backward) += 1;
        }
    }
    for (const auto& [key, uses] : edges) {
        const uint32_t total = uses.forward + uses.backward;
        if (total == 1) ++q.boundaryEdges;
        if (total > 2) ++q.nonManifoldEdges;
        if (total == 2 && uses.forward != 1) ++q.misorientedEdges;
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
