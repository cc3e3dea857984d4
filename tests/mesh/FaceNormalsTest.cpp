// Vertex normals against triangle winding (orientNormalsToFaces): on fields full of features
// thinner than the gradient's central differences, every triangle of both meshers has all three
// vertex normals within 90 degrees of its geometric normal, for every chunk size and for a mesh
// cut into boxes of cells (world tiles); a fold no single normal can face splits its vertex.
#include "TestGrids.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/mesh/MeshQuality.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <gtest/gtest.h>
#include <random>
#include <tuple>

namespace voxc {
namespace face_normals_test {


// Triangles with area whose vertex normals include one more than 90 degrees from their normal.
size_t trianglesAgainstTheirNormals(const Mesh& mesh) {
    size_t against = 0;
    for (size_t t = 0; t < mesh.triangles.size() / 3; ++t) {
        const glm::dvec3 f = triangleNormal(mesh, t);
        if (f == glm::dvec3(0.0)) continue;
        bool bad = false;
        for (int k = 0; k < 3; ++k) bad |= glm::dot(glm::dvec3(mesh.normals[mesh.triangles[t * 3 + size_t(k)]]), f) < 0.0;
        against += bad;
    }
    return against;
}

void expectNormalsFaceTheirTriangles(const Mesh& mesh, const std::string& what) {
    ASSERT_FALSE(mesh.triangles.empty()) << what;
    EXPECT_EQ(trianglesAgainstTheirNormals(mesh), 0u) << what;
    for (const glm::vec3& n : mesh.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f) << what;
}

TEST(mesh_FaceNormals, fieldGradientsTurnAgainstThinFeaturesWithoutTheStep) {
    // The meshers' own normals (the field gradient, before this step) face away from some
    // triangles on this field, so the tests below exercise the re-derivation.
    const ChunkedGrid grid = test::noiseGrid({-3, 5, 2}, {24, 20, 22}, 8, 7);
    std::vector<marching_cubes::ChunkMesh> parts;
    for (int z = -1; z <= 3; ++z)
        for (int y = 0; y <= 3; ++y)
            for (int x = -1; x <= 3; ++x) parts.push_back(marching_cubes::extractChunk(grid, 0.5f, {x, y, z}));
    std::vector<marching_cubes::EdgeVertex> vertices;
    for (const auto& part : parts) vertices.insert(vertices.end(), part.vertices.begin(), part.vertices.end());
    const Mesh mesh = marching_cubes::mergeChunks(parts);
    // Put the gradient normals back, by edge, and count the triangles they face away from.
    std::sort(vertices.begin(), vertices.end(), [](const auto& a, const auto& b) { return a.edge < b.edge; });
    vertices.erase(std::unique(vertices.begin(), vertices.end(), [](const auto& a, const auto& b) { return a.edge == b.edge; }), vertices.end());
    ASSERT_EQ(vertices.size(), mesh.positions.size() - mesh.normalSplits.size());
    Mesh raw = mesh;
    for (size_t v = 0; v < raw.positions.size(); ++v)
        raw.normals[v] = vertices[v < vertices.size() ? v : raw.normalSplits[v - vertices.size()]].normal;
    EXPECT_GT(trianglesAgainstTheirNormals(raw), 100u);
    EXPECT_EQ(trianglesAgainstTheirNormals(mesh), 0u);
    EXPECT_FALSE(mesh.normalSplits.empty()) << "no fold needed a split vertex";
}

TEST(mesh_FaceNormals, bothMeshersAtEveryChunkSizeAndOrigin) {
    for (glm::ivec3 origin : {glm::ivec3(0), glm::ivec3(-37, 5, -70), glm::ivec3(1000, 17, -999)}) {
        std::vector<Mesh> mc;
        for (int32_t chunk : {8, 16, 32}) {
            const ChunkedGrid grid = test::noiseGrid(origin, {29, 23, 26}, chunk, 3);
            const std::string at = " chunk " + std::to_string(chunk);
            mc.push_back(meshMarchingCubes(grid, MeshOptions{}));
            expectNormalsFaceTheirTriangles(mc.back(), "marching cubes" + at);
            // The split copies are the same points: the mesh stays closed and manifold.
            const MeshQuality q = measureMeshQuality(mc.back());
            EXPECT_TRUE(q.manifold()) << describeMeshQuality(q);
            EXPECT_EQ(std::memcmp(mc.back().positions.data(), mc.front().positions.data(), mc.front().positions.size() * 12), 0);
            EXPECT_EQ(std::memcmp(mc.back().normals.data(), mc.front().normals.data(), mc.front().normals.size() * 12), 0);
            EXPECT_EQ(mc.back().triangles, mc.front().triangles);
            EXPECT_EQ(mc.back().normalSplits, mc.front().normalSplits);
            for (float iso : {0.5f, 0.25f}) expectNormalsFaceTheirTriangles(meshSurfaceNets(grid, iso), "surface nets" + at);
        }
    }
}

// A vertex and its normal by their bits, for comparing meshes numbered differently.
using Corner = std::tuple<std::array<uint32_t, 3>, std::array<uint32_t, 3>>;
std::vector<std::array<Corner, 3>> cornerTriangles(const Mesh& mesh) {
    auto bits = [](glm::vec3 v) {
        std::array<uint32_t, 3> out;
        std::memcpy(out.data(), &v, 12);
        return out;
    };
    std::vector<std::array<Corner, 3>> out;
    for (size_t t = 0; t < mesh.triangles.size() / 3; ++t) {
        std::array<Corner, 3> c;
        for (size_t k = 0; k < 3; ++k) {
            const uint32_t v = mesh.triangles[t * 3 + k];
            c[k] = {bits(mesh.positions[v]), bits(mesh.normals[v])};
        }
        out.push_back(c);
    }
    std::sort(out.begin(), out.end());
    return out;
}

TEST(mesh_FaceNormals, boxesOfCellsCarryTheWholeMeshsNormals) {
    const ChunkedGrid grid = test::noiseGrid({4, -2, 9}, {26, 21, 24}, 16, 5);
    const float margin = marching_cubes::crossingMargin(grid.layout());
    const Mesh whole = meshMarchingCubes(grid, MeshOptions{});
    std::vector<std::array<Corner, 3>> fromBoxes;
    for (int z : {-1, 11})
        for (int x : {-1, 9, 17}) {
            const CellBox box{{x, -1, z}, {x == 17 ? 26 : x == -1 ? 9 : 17, 21, z == -1 ? 11 : 24}};
            const Mesh part = meshMarchingCubesCells(grid, box, margin, MeshOptions{});
            expectNormalsFaceTheirTriangles(part, "a box of cells");
            const auto corners = cornerTriangles(part);
            fromBoxes.insert(fromBoxes.end(), corners.begin(), corners.end());
        }
    std::sort(fromBoxes.begin(), fromBoxes.end());
    EXPECT_TRUE(fromBoxes == cornerTriangles(whole));
}

TEST(mesh_FaceNormals, aFoldNoNormalCanFaceSplitsItsVertex) {
    // Two triangles back to back in one plane around vertex 0, then one beside the first: no
    // normal is more than 90 degrees from all three by the margin, so 0 is split.
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {0, 2, 0}, {-1, 0, 0}};
    mesh.normals.assign(6, glm::vec3(0, 0, 1));
    mesh.triangles = {0, 1, 2, 0, 4, 3, 0, 2, 5};
    mesh.vertexMaterials = {1, 2, 3, 4, 5, 6};
    EXPECT_EQ(orientNormalsToFaces(mesh), 3u); // 0 split, 3 and 4 turned
    EXPECT_EQ(mesh.normals[0], glm::vec3(0, 0, 1));
    EXPECT_EQ(mesh.normals[3], glm::vec3(0, 0, -1));
    ASSERT_EQ(mesh.normalSplits, std::vector<uint32_t>{0});
    ASSERT_EQ(mesh.positions.size(), 7u);
    EXPECT_EQ(mesh.positions[6], mesh.positions[0]);
    EXPECT_EQ(mesh.vertexMaterials[6], 1);
    EXPECT_EQ(mesh.triangles, (std::vector<uint32_t>{0, 1, 2, 6, 4, 3, 0, 2, 5}));
    EXPECT_EQ(trianglesAgainstTheirNormals(mesh), 0u);
    EXPECT_EQ(analyzeTopology(mesh).boundaryEdges, analyzeTopology(Mesh{mesh.positions, mesh.normals, {0, 1, 2, 0, 4, 3, 0, 2, 5}}).boundaryEdges);
}

} // namespace face_normals_test
} // namespace voxc
