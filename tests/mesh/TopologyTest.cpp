#include "voxc/mesh/Mesh.h"

#include <gtest/gtest.h>

namespace voxc {
namespace topology_test {

// A tetrahedron wound counter-clockwise seen from outside.
Mesh tetrahedron() {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.normals.assign(4, glm::vec3(0, 0, 1));
    mesh.triangles = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    return mesh;
}

TEST(mesh_Topology, closedConsistentTetrahedronIsWatertight) {
    const MeshTopology t = analyzeTopology(tetrahedron());
    EXPECT_TRUE(t.watertight());
    EXPECT_EQ(t.boundaryEdges, 0u);
    EXPECT_EQ(t.nonManifoldEdges, 0u);
    EXPECT_EQ(t.degenerateTriangles, 0u);
    EXPECT_EQ(t.duplicateTriangles, 0u);
    EXPECT_EQ(t.misorientedEdges, 0u);
}

TEST(mesh_Topology, missingFaceLeavesBoundaryEdges) {
    Mesh mesh = tetrahedron();
    mesh.triangles.resize(9);
    const MeshTopology t = analyzeTopology(mesh);
    EXPECT_FALSE(t.watertight());
    EXPECT_EQ(t.boundaryEdges, 3u);
}

TEST(mesh_Topology, repeatedFaceIsDuplicateAndNonManifold) {
    Mesh mesh = tetrahedron();
    mesh.triangles.insert(mesh.triangles.end(), {2, 3, 1});
    const MeshTopology t = analyzeTopology(mesh);
    EXPECT_FALSE(t.watertight());
    EXPECT_EQ(t.duplicateTriangles, 1u);
    EXPECT_EQ(t.nonManifoldEdges, 3u);
}

TEST(mesh_Topology, flippedFaceIsMisoriented) {
    Mesh mesh = tetrahedron();
    std::swap(mesh.triangles[10], mesh.triangles[11]);
    const MeshTopology t = analyzeTopology(mesh);
    EXPECT_TRUE(t.watertight());
    EXPECT_EQ(t.misorientedEdges, 3u);
}

TEST(mesh_Topology, repeatedIndexAndZeroAreaAreDegenerate) {
    Mesh mesh = tetrahedron();
    mesh.positions.push_back({2, 0, 0});
    mesh.normals.push_back({0, 0, 1});
    mesh.triangles.insert(mesh.triangles.end(), {0, 0, 1, 0, 1, 4});
    EXPECT_EQ(analyzeTopology(mesh).degenerateTriangles, 2u);
}

} // namespace topology_test
} // namespace voxc
