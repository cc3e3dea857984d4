#include "TestGrids.h"
#include "voxc/mesh/SurfaceNets.h"

#include <gtest/gtest.h>

namespace voxc {
namespace surface_nets_test {

using test::box;
using test::coneBall;
using test::makeGrid;

void expectClosedAndClean(const Mesh& mesh) {
    const MeshTopology topology = analyzeTopology(mesh);
    EXPECT_TRUE(topology.watertight()) << topology.boundaryEdges << " boundary, " << topology.nonManifoldEdges << " non-manifold";
    EXPECT_EQ(topology.duplicateTriangles, 0u);
    EXPECT_EQ(topology.degenerateTriangles, 0u);
    EXPECT_EQ(topology.misorientedEdges, 0u);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (const glm::vec3& n : mesh.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
}

glm::vec3 faceNormal(const Mesh& mesh, size_t t) {
    const glm::vec3 a = mesh.positions[mesh.triangles[t]], b = mesh.positions[mesh.triangles[t + 1]], c = mesh.positions[mesh.triangles[t + 2]];
    return glm::cross(b - a, c - a);
}

TEST(mesh_SurfaceNets, sphereIsClosedWithOutwardNormalsAndWinding) {
    const glm::vec3 centre(16.3f, 15.7f, 16.1f);
    const Mesh mesh = meshSurfaceNets(makeGrid({0, 0, 0}, {33, 33, 33}, 16, coneBall(centre, 20.0f)), 0.5f);
    ASSERT_FALSE(mesh.triangles.empty());
    expectClosedAndClean(mesh);
    for (size_t v = 0; v < mesh.positions.size(); ++v) EXPECT_GT(glm::dot(mesh.normals[v], glm::normalize(mesh.positions[v] - centre)), 0.9f);
    for (size_t t = 0; t < mesh.triangles.size(); t += 3) {
        const glm::vec3 centroid = (mesh.positions[mesh.triangles[t]] + mesh.positions[mesh.triangles[t + 1]] + mesh.positions[mesh.triangles[t + 2]]) / 3.0f;
        EXPECT_GT(glm::dot(faceNormal(mesh, t), centroid - centre), 0.0f);
    }
}

TEST(mesh_SurfaceNets, verticesLieOnTheIsoLevel) {
    const glm::vec3 centre(20.0f, 20.0f, 20.0f);
    const ChunkedGrid grid = makeGrid({0, 0, 0}, {41, 41, 41}, 16, coneBall(centre, 18.0f));
    for (float iso : {0.25f, 0.5f, 0.7f}) {
        const Mesh mesh = meshSurfaceNets(grid, iso);
        ASSERT_FALSE(mesh.positions.empty());
        const float radius = 18.0f * (1.0f - iso);
        // Centres of mass of edge crossings sit slightly inside a convex surface.
        for (const glm::vec3& p : mesh.positions) EXPECT_NEAR(glm::length(p - centre), radius, 0.15f) << "iso " << iso;
    }
}

TEST(mesh_SurfaceNets, emptyGridGivesEmptyMesh) {
    const Mesh mesh = meshSurfaceNets(makeGrid({-5, 3, 9}, {20, 12, 7}, 8, [](glm::vec3) { return 0.0f; }), 0.5f);
    EXPECT_TRUE(mesh.positions.empty());
    EXPECT_TRUE(mesh.normals.empty());
    EXPECT_TRUE(mesh.triangles.empty());
}

// Checks a closed box surface of solid voxels [lo, hi) (world): the vertices of cells whose
// four crossed edges all cross one face lie exactly halfway to the air, half a voxel outside.
void expectBoxSurface(const Mesh& mesh, glm::ivec3 lo, glm::ivec3 hi) {
    expectClosedAndClean(mesh);
    const glm::vec3 faceLo = glm::vec3(lo) - 0.5f, faceHi = glm::vec3(hi) - 0.5f, mid = (faceLo + faceHi) * 0.5f;
    const glm::ivec3 extent = hi - lo;
    for (int a = 0; a < 3; ++a) {
        const int u = (a + 1) % 3, v = (a + 2) % 3;
        size_t onLow = 0, onHigh = 0;
        for (const glm::vec3& p : mesh.positions) {
            onLow += p[a] == faceLo[a];
            onHigh += p[a] == faceHi[a];
        }
        EXPECT_EQ(onLow, size_t((extent[u] - 1) * (extent[v] - 1))) << "axis " << a;
        EXPECT_EQ(onHigh, size_t((extent[u] - 1) * (extent[v] - 1))) << "axis " << a;
    }
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3 p = mesh.positions[v];
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, faceLo - 0.5f)) && glm::all(glm::lessThanEqual(p, faceHi + 0.5f)));
        EXPECT_GT(glm::dot(mesh.normals[v], p - mid), 0.0f);
    }
    // The bevelled box is convex, so every face turns away from its centre.
    for (size_t t = 0; t < mesh.triangles.size(); t += 3) EXPECT_GT(glm::dot(faceNormal(mesh, t), mesh.positions[mesh.triangles[t]] - mid), 0.0f);
}

TEST(mesh_SurfaceNets, solidGridIsClosedByTheOutsideAir) {
    const glm::ivec3 size(10, 7, 5), origin(-3, 2, 40);
    const Mesh mesh = meshSurfaceNets(makeGrid(origin, size, 8, [](glm::vec3) { return 1.0f; }), 0.5f);
    expectBoxSurface(mesh, origin, origin + size);
    // A vertex in every cell of the one-voxel shell around the grid, a quad per boundary voxel face.
    const glm::ivec3 outer = size + 1, inner = size - 1;
    EXPECT_EQ(mesh.positions.size(), size_t(outer.x * outer.y * outer.z - inner.x * inner.y * inner.z));
    EXPECT_EQ(mesh.triangles.size() / 3, size_t(4 * (size.x * size.y + size.y * size.z + size.z * size.x)));
}

TEST(mesh_SurfaceNets, boxInsideTheGridIsClosed) {
    const glm::ivec3 lo(3, 4, 5), hi(12, 9, 15);
    expectBoxSurface(meshSurfaceNets(makeGrid({0, 0, 0}, {16, 16, 20}, 8, box(lo, hi)), 0.5f), lo, hi);
}

// Two voxels touching along one edge make a saddle face: the mesh stays closed, and the
// four quads at the ambiguous face share one edge (documented in SurfaceNets.h).
TEST(mesh_SurfaceNets, saddleFaceIsClosedButNotManifold) {
    const Mesh mesh = meshSurfaceNets(makeGrid({0, 0, 0}, {4, 4, 3}, 8, [](glm::vec3 p) {
        return (p == glm::vec3(1, 1, 1) || p == glm::vec3(2, 2, 1)) ? 1.0f : 0.0f;
    }), 0.5f);
    const MeshTopology topology = analyzeTopology(mesh);
    EXPECT_TRUE(topology.closed());
    EXPECT_FALSE(topology.watertight());
    EXPECT_EQ(topology.nonManifoldEdges, 1u);
    EXPECT_EQ(topology.duplicateTriangles, 0u);
    EXPECT_EQ(topology.misorientedEdges, 0u);
}

} // namespace surface_nets_test
} // namespace voxc

namespace voxc {

// With the grid's tile ranges the uniform-chunk test answers from them without reading voxels,
// and a chunk's uniform 8^3 tiles of cells are passed over; neither skips a cell the samples
// would not: the same mesh, bit for bit, and the same chunks skipped, with and without ranges, at tile-aligned and unaligned origins, chunks below and above
// the tile's size, and an iso below 0 (the outside of the grid solid).
TEST(mesh_SurfaceNets, tileRangesSkipTheSameChunksAndGiveTheSameMesh) {
    struct Case {
        glm::ivec3 origin;
        int32_t chunk;
        float iso;
    };
    for (const Case& c : {Case{{0, 0, 0}, 8, 0.5f}, Case{{-5, 3, -11}, 16, 0.5f}, Case{{4, -9, 2}, 4, 0.3f}, Case{{-5, 3, -11}, 16, -0.25f}}) {
        const ChunkedGrid plain = test::makeGrid(c.origin, {45, 38, 41}, c.chunk, test::coneBall(glm::vec3(c.origin) + glm::vec3(20.3f, 17.6f, 19.1f), 26.0f));
        ChunkedGrid ranged = plain;
        ranged.recordTileRanges();
        ASSERT_EQ(plain.tileRanges(), nullptr);
        ASSERT_NE(ranged.tileRanges(), nullptr);
        MeshStats plainStats, rangedStats;
        const Mesh a = meshSurfaceNets(plain, MeshOptions{.iso = c.iso}, &plainStats);
        const Mesh b = meshSurfaceNets(ranged, MeshOptions{.iso = c.iso}, &rangedStats);
        EXPECT_TRUE(a.positions == b.positions && a.normals == b.normals) << "chunk " << c.chunk << " iso " << c.iso;
        EXPECT_EQ(a.triangles, b.triangles);
        EXPECT_EQ(a.vertexMaterials, b.vertexMaterials);
        EXPECT_EQ(a.triangleMaterials, b.triangleMaterials);
        EXPECT_EQ(plainStats.skippedChunks, rangedStats.skippedChunks);
        EXPECT_GT(rangedStats.skippedChunks, 0u) << "chunk " << c.chunk << " iso " << c.iso;
        if (c.iso >= 0.0f) EXPECT_FALSE(b.triangles.empty());
    }
}

} // namespace voxc
