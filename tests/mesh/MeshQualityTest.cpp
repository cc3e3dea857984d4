// The independent mesh checker on hand-made meshes, each broken in one known way.
#include "voxc/mesh/MeshQuality.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace voxc {
namespace mesh_quality_test {

// A unit tetrahedron, counter-clockwise seen from outside.
Mesh tetrahedron() {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.normals = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.triangles = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    return m;
}

TEST(mesh_Quality, closedTetrahedronIsManifoldWithItsVolume) {
    const MeshQuality q = measureMeshQuality(tetrahedron());
    EXPECT_TRUE(q.manifold());
    EXPECT_EQ(q.vertices, 4u);
    EXPECT_EQ(q.triangles, 4u);
    EXPECT_EQ(q.zeroAreaTriangles, 0u);
    EXPECT_DOUBLE_EQ(q.signedVolume, 1.0 / 6.0);
    EXPECT_EQ(describeMeshQuality(q), "4 vertices, 4 triangles, 0 boundary edges, 0 non-manifold edges, 0 zero-area triangles");
}

TEST(mesh_Quality, missingTriangleLeavesThreeBoundaryEdges) {
    Mesh m = tetrahedron();
    m.triangles.resize(9);
    const MeshQuality q = measureMeshQuality(m);
    EXPECT_EQ(q.boundaryEdges, 3u);
    EXPECT_FALSE(q.manifold());
}

TEST(mesh_Quality, flippedTriangleMisorientsItsThreeEdges) {
    Mesh m = tetrahedron();
    std::swap(m.triangles[10], m.triangles[11]);
    const MeshQuality q = measureMeshQuality(m);
    EXPECT_EQ(q.misorientedEdges, 3u);
    EXPECT_EQ(q.boundaryEdges, 0u);
    EXPECT_FALSE(q.manifold());
    EXPECT_NE(describeMeshQuality(q).find("3 misoriented edges"), std::string::npos);
}

TEST(mesh_Quality, inwardFacingMeshHasNegativeVolume) {
    Mesh m = tetrahedron();
    for (size_t t = 0; t < m.triangles.size(); t += 3) std::swap(m.triangles[t + 1], m.triangles[t + 2]);
    const MeshQuality q = measureMeshQuality(m);
    EXPECT_EQ(q.misorientedEdges, 0u);
    EXPECT_DOUBLE_EQ(q.signedVolume, -1.0 / 6.0);
}

// Two tetrahedra glued along one edge (0-1): that edge has four triangles.
TEST(mesh_Quality, fourTrianglesOnAnEdgeAreNonManifold) {
    Mesh m = tetrahedron();
    const uint32_t base = uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), {{0, -1, 0}, {0, 0, -1}});
    m.normals.resize(m.positions.size(), glm::vec3(0, 1, 0));
    // The second tetrahedron reuses vertices 0 and 1.
    const uint32_t a = 0, b = 1, c = base, d = base + 1;
    m.triangles.insert(m.triangles.end(), {a, c, b, a, b, d, a, d, c, b, c, d});
    const MeshQuality q = measureMeshQuality(m);
    EXPECT_EQ(q.nonManifoldEdges, 1u);
    EXPECT_EQ(q.boundaryEdges, 0u);
}

TEST(mesh_Quality, distinctVerticesAtOnePointMakeZeroAreaTriangles) {
    Mesh m = tetrahedron();
    m.positions.push_back(m.positions[0]); // vertex 4 coincides with 0
    m.normals.push_back(m.normals[0]);
    m.triangles.insert(m.triangles.end(), {0, 4, 1, 0, 1, 2}); // one collapsed, one fine (but a duplicate face)
    const MeshQuality q = measureMeshQuality(m);
    EXPECT_EQ(q.zeroAreaTriangles, 1u);
    EXPECT_EQ(q.repeatedIndexTriangles, 0u);
}

TEST(mesh_Quality, collinearVerticesMakeAZeroAreaTriangle) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    m.normals.resize(3, glm::vec3(0, 1, 0));
    m.triangles = {0, 1, 2};
    EXPECT_EQ(measureMeshQuality(m).zeroAreaTriangles, 1u);
}

TEST(mesh_Quality, repeatedAndOutOfRangeIndicesAreCountedNotFollowed) {
    Mesh m = tetrahedron();
    m.triangles.insert(m.triangles.end(), {1, 1, 2, 0, 1, 99});
    const MeshQuality q = measureMeshQuality(m);
    EXPECT_EQ(q.repeatedIndexTriangles, 1u);
    EXPECT_EQ(q.badIndexTriangles, 1u);
    EXPECT_FALSE(q.manifold());
}

TEST(mesh_Quality, nonFiniteVerticesAreCounted) {
    Mesh m = tetrahedron();
    m.positions[1].y = std::numeric_limits<float>::quiet_NaN();
    m.normals[2].z = std::numeric_limits<float>::infinity();
    const MeshQuality q = measureMeshQuality(m);
    EXPECT_EQ(q.nonFiniteVertices, 2u);
    EXPECT_NE(describeMeshQuality(q).find("2 non-finite vertices"), std::string::npos);
}

TEST(mesh_Quality, emptyMeshIsTriviallyManifold) {
    const MeshQuality q = measureMeshQuality(Mesh{});
    EXPECT_TRUE(q.manifold());
    EXPECT_EQ(q.triangles, 0u);
}

} // namespace mesh_quality_test
} // namespace voxc
