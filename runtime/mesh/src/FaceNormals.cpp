#include "voxc/mesh/Mesh.h"

#include "ChunkWorkers.h"

#include <algorithm>
#include <atomic>
#include <glm/geometric.hpp>

namespace voxc {

namespace {

// The least cosine a re-derived normal keeps to each of its triangles where it can: far enough
// above zero that rounding the normal to float cannot turn a triangle away from it.
constexpr double kMinCosine = 1e-3;

// Triangles per block of the search for vertices to re-derive: a small mesh is one block, on the
// calling thread.
constexpr size_t kTrianglesPerBlock = size_t(1) << 16;

double leastCosine(const glm::dvec3& n, const std::vector<glm::dvec3>& faces) {
    double least = 2.0;
    for (const glm::dvec3& f : faces) least = std::min(least, glm::dot(n, f));
    return least;
}

// The direction for a vertex whose unit face normals are `faces`: their normalised sum where that
// keeps within 90 degrees of each (the smooth choice), else the centre of the smallest cap of the
// sphere holding them all, the direction whose largest angle to a face is least. That centre is
// fixed by two or three of the faces (the midpoint of two, or the point equally far from three),
// so every pair and triple is a candidate; vertices come here rarely and have few triangles.
glm::dvec3 facingDirection(const std::vector<glm::dvec3>& faces) {
    glm::dvec3 sum(0.0);
    for (const glm::dvec3& f : faces) sum += f;
    glm::dvec3 best = faces.front();
    double bestLeast = leastCosine(best, faces);
    auto consider = [&](const glm::dvec3& candidate) {
        const double length = glm::length(candidate);
        if (!(length > 0.0)) return;
        const glm::dvec3 n = candidate / length;
        const double least = leastCosine(n, faces);
        if (least > bestLeast) best = n, bestLeast = least;
    };
    consider(sum);
    if (bestLeast >= kMinCosine && best != faces.front()) return best;
    const size_t k = faces.size();
    for (size_t i = 0; i < k; ++i) {
        consider(faces[i]);
        for (size_t j = i + 1; j < k; ++j) {
            consider(faces[i] + faces[j]);
            for (size_t l = j + 1; l < k; ++l) {
                const glm::dvec3 centre = glm::cross(faces[j] - faces[i], faces[l] - faces[i]);
                consider(centre);
                consider(-centre);
            }
        }
    }
    return best;
}

} // namespace

glm::dvec3 triangleNormal(const Mesh& mesh, size_t triangle) {
    const glm::dvec3 a(mesh.positions[mesh.triangles[triangle * 3]]);
    const glm::dvec3 b(mesh.positions[mesh.triangles[triangle * 3 + 1]]);
    const glm::dvec3 c(mesh.positions[mesh.triangles[triangle * 3 + 2]]);
    return glm::cross(b - a, c - a);
}

size_t orientNormalsToFaces(Mesh& mesh) {
    const size_t vertexCount = mesh.positions.size(), triangleCount = mesh.triangles.size() / 3;
    // One pass finds the vertices to re-derive (few: thin features, vanished gradients).
    std::vector<uint32_t> incident(vertexCount + 1, 0); // per vertex to re-derive: its triangle count, then offsets
    std::vector<uint8_t> against(vertexCount, 0);
    for (size_t v = 0; v < vertexCount; ++v) against[v] = mesh.normals[v] == glm::vec3(0.0f);
    // Large meshes on the mesh workers, in blocks of triangles; a flag is only ever set to 1, so
    // the result does not depend on the threads.
    const size_t blocks = (triangleCount + kTrianglesPerBlock - 1) / kTrianglesPerBlock;
    forEachChunk(blocks, [&](size_t block) {
        const size_t end = std::min(triangleCount, (block + 1) * kTrianglesPerBlock);
        for (size_t t = block * kTrianglesPerBlock; t < end; ++t) {
            const glm::dvec3 f = triangleNormal(mesh, t);
            if (f == glm::dvec3(0.0)) continue;
            for (int k = 0; k < 3; ++k) {
                const uint32_t v = mesh.triangles[t * 3 + size_t(k)];
                if (glm::dot(glm::dvec3(mesh.normals[v]), f) < 0.0) std::atomic_ref<uint8_t>(against[v]).store(1, std::memory_order_relaxed);
            }
        }
        return true;
    });
    if (std::find(against.begin(), against.end(), uint8_t(1)) == against.end()) return 0;

    // Their triangles, in triangle order, so the sums do not depend on anything but the mesh.
    for (size_t t = 0; t < triangleCount; ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.triangles[t * 3 + size_t(k)];
            if (against[v]) ++incident[v + 1];
        }
    for (size_t v = 0; v < vertexCount; ++v) incident[v + 1] += incident[v];
    std::vector<uint32_t> fill(incident.begin(), incident.end() - 1), triangles(incident.back());
    for (size_t t = 0; t < triangleCount; ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.triangles[t * 3 + size_t(k)];
            if (against[v]) triangles[fill[v]++] = uint32_t(t);
        }
    return orientFlaggedNormals(mesh, against, incident, triangles);
}

size_t orientFlaggedNormals(Mesh& mesh, const std::vector<uint8_t>& against, const std::vector<uint32_t>& incident,
                            const std::vector<uint32_t>& triangles) {
    const size_t vertexCount = against.size();
    size_t changed = 0;
    for (size_t v = 0; v < vertexCount; ++v) changed += against[v];
    if (changed == 0) return 0;

    struct Group {
        std::vector<glm::dvec3> faces;
        std::vector<uint32_t> triangles;
        glm::dvec3 normal;
    };
    std::vector<Group> groups;
    std::vector<glm::dvec3> trial;
    for (size_t v = 0; v < vertexCount; ++v) {
        if (!against[v]) continue;
        // Zero-area triangles have no side; they follow the group of the vertex itself.
        groups.assign(1, Group{});
        for (uint32_t i = incident[v]; i < incident[v + 1]; ++i) {
            const glm::dvec3 f = triangleNormal(mesh, triangles[i]);
            if (f == glm::dvec3(0.0)) continue;
            const glm::dvec3 unit = glm::normalize(f);
            bool placed = false;
            for (Group& g : groups) {
                if (g.faces.empty()) {
                    g.faces.push_back(unit), g.triangles.push_back(triangles[i]), g.normal = unit;
                    placed = true;
                    break;
                }
                // The group's direction so far may already face the new triangle; else search.
                glm::dvec3 n = g.normal;
                if (glm::dot(n, unit) < kMinCosine) {
                    trial = g.faces;
                    trial.push_back(unit);
                    n = facingDirection(trial);
                    if (leastCosine(n, trial) < kMinCosine) continue;
                }
                g.faces.push_back(unit), g.triangles.push_back(triangles[i]), g.normal = n;
                placed = true;
                break;
            }
            if (!placed) groups.push_back(Group{{unit}, {triangles[i]}, unit});
        }
        // A vertex of zero-area triangles only has no face to follow; its normal stays.
        if (groups.front().faces.empty()) {
            --changed;
            continue;
        }
        // Each group's normal from all its triangles at once: their sum where it faces them all.
        for (Group& g : groups) g.normal = facingDirection(g.faces);
        mesh.normals[v] = glm::vec3(groups.front().normal);
        for (size_t g = 1; g < groups.size(); ++g) {
            const uint32_t copy = uint32_t(mesh.positions.size());
            mesh.positions.push_back(mesh.positions[v]);
            mesh.normals.push_back(glm::vec3(groups[g].normal));
            if (v < mesh.vertexMaterials.size()) mesh.vertexMaterials.push_back(mesh.vertexMaterials[v]);
            mesh.normalSplits.push_back(uint32_t(v));
            for (uint32_t t : groups[g].triangles)
                for (int k = 0; k < 3; ++k)
                    if (mesh.triangles[size_t(t) * 3 + size_t(k)] == v) mesh.triangles[size_t(t) * 3 + size_t(k)] = copy;
        }
    }
    return changed;
}

} // namespace voxc
