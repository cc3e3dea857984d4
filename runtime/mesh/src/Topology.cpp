#include "voxc/mesh/Mesh.h"

#include <algorithm>
#include <array>
#include <glm/geometric.hpp>

namespace voxc {

MeshTopology analyzeTopology(const Mesh& mesh) {
    MeshTopology topology;
    struct EdgeUse {
        uint64_t key;  // (smaller index << 32) | larger index
        bool forward;  // traversed from the smaller index to the larger
    };
    std::vector<EdgeUse> edges;
    std::vector<std::array<uint32_t, 3>> faces;
    edges.reserve(mesh.triangles.size());
    faces.reserve(mesh.triangles.size() / 3);
    // A copy made for its normal is the point it copies (Mesh::normalSplits).
    const size_t firstCopy = mesh.positions.size() - mesh.normalSplits.size();
    auto point = [&](uint32_t v) { return v >= firstCopy ? mesh.normalSplits[v - firstCopy] : v; };
    for (size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
        const std::array<uint32_t, 3> f = {point(mesh.triangles[t]), point(mesh.triangles[t + 1]), point(mesh.triangles[t + 2])};
        if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) {
            ++topology.degenerateTriangles;
        } else {
            const glm::vec3 &a = mesh.positions[f[0]], &b = mesh.positions[f[1]], &c = mesh.positions[f[2]];
            if (glm::cross(b - a, c - a) == glm::vec3(0.0f)) ++topology.degenerateTriangles;
        }
        for (int k = 0; k < 3; ++k) {
            const uint32_t from = f[size_t(k)], to = f[size_t((k + 1) % 3)];
            if (from == to) continue;
            const uint32_t lo = std::min(from, to), hi = std::max(from, to);
            edges.push_back({uint64_t(lo) << 32 | hi, from == lo});
        }
        std::array<uint32_t, 3> sorted = f;
        std::sort(sorted.begin(), sorted.end());
        faces.push_back(sorted);
    }

    std::sort(edges.begin(), edges.end(), [](const EdgeUse& a, const EdgeUse& b) { return a.key < b.key; });
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        while (j < edges.size() && edges[j].key == edges[i].key) ++j;
        const size_t uses = j - i;
        if (uses == 1) ++topology.boundaryEdges;
        if (uses > 2) ++topology.nonManifoldEdges;
        if (uses == 2 && edges[i].forward == edges[i + 1].forward) ++topology.misorientedEdges;
        i = j;
    }

    std::sort(faces.begin(), faces.end());
    for (size_t i = 1; i < faces.size(); ++i)
        if (faces[i] == faces[i - 1]) ++topology.duplicateTriangles;
    return topology;
}

} // namespace voxc
