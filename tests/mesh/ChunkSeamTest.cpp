// Chunking must not show in the mesh: shapes straddling chunk borders, at negative and far
// origins, give the same vertices, triangles and materials in the same order for every chunk size.
#include "TestGrids.h"
#include "voxc/mesh/SurfaceNets.h"

#include <algorithm>
#include <array>
#include <gtest/gtest.h>
#include <tuple>

namespace voxc {
namespace chunk_seam_test {

using test::makeGrid;

const glm::ivec3 kSize(45, 30, 50);

// A ball and a slab that cross chunk borders at every chunk size, given relative to the origin.
std::function<float(glm::vec3)> straddlingShape(glm::ivec3 origin) {
    const auto ball = test::coneBall(glm::vec3(origin) + glm::vec3(20.4f, 14.2f, 23.7f), 24.0f);
    const auto slab = test::box(glm::vec3(origin) + glm::vec3(5, 3, 9), glm::vec3(origin) + glm::vec3(41, 9, 44));
    return [=](glm::vec3 p) { return std::max(ball(p), slab(p)); };
}

using Triangle = std::array<float, 9>;

// Triangles as vertex positions, each rotated to start at its smallest vertex, then sorted.
std::vector<Triangle> triangleSet(const Mesh& mesh) {
    std::vector<Triangle> set;
    for (size_t t = 0; t < mesh.triangles.size(); t += 3) {
        std::array<glm::vec3, 3> corners;
        for (size_t k = 0; k < 3; ++k) corners[k] = mesh.positions[mesh.triangles[t + k]];
        auto less = [](glm::vec3 a, glm::vec3 b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); };
        std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end(), less), corners.end());
        Triangle tri;
        for (size_t k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a) tri[k * 3 + size_t(a)] = corners[k][a];
        set.push_back(tri);
    }
    std::sort(set.begin(), set.end());
    return set;
}

class mesh_ChunkSeams : public testing::TestWithParam<glm::ivec3> {};

// Materials in slanted bands, so every chunk border cuts through several of them.
ChunkedGrid straddlingGrid(glm::ivec3 origin, int32_t chunkSize) {
    ChunkedGrid grid = makeGrid(origin, kSize, chunkSize, straddlingShape(origin));
    test::paintMaterials(grid, [&](glm::ivec3 p) {
        const glm::ivec3 q = p - origin;
        return uint8_t(1 + (q.x + 2 * q.y + q.z) / 7 % 5);
    });
    return grid;
}

TEST_P(mesh_ChunkSeams, meshIsIdenticalForEveryChunkSize) {
    const glm::ivec3 origin = GetParam();
    const Mesh reference = meshSurfaceNets(straddlingGrid(origin, 8), 0.5f);
    const MeshTopology topology = analyzeTopology(reference);
    EXPECT_TRUE(topology.watertight());
    EXPECT_EQ(topology.duplicateTriangles, 0u);
    EXPECT_EQ(topology.misorientedEdges, 0u);
    ASSERT_GT(reference.triangles.size(), 1000u);
    const std::vector<Triangle> referenceSet = triangleSet(reference);
    ASSERT_NE(std::count(reference.triangleMaterials.begin(), reference.triangleMaterials.end(), uint8_t(5)), 0);
    for (int32_t chunkSize : {16, 32}) {
        const Mesh mesh = meshSurfaceNets(straddlingGrid(origin, chunkSize), 0.5f);
        EXPECT_EQ(triangleSet(mesh), referenceSet) << "chunk size " << chunkSize;
        EXPECT_EQ(mesh.positions, reference.positions) << "chunk size " << chunkSize;
        EXPECT_EQ(mesh.normals, reference.normals) << "chunk size " << chunkSize;
        EXPECT_EQ(mesh.triangles, reference.triangles) << "chunk size " << chunkSize;
        EXPECT_EQ(mesh.vertexMaterials, reference.vertexMaterials) << "chunk size " << chunkSize;
        EXPECT_EQ(mesh.triangleMaterials, reference.triangleMaterials) << "chunk size " << chunkSize;
    }
}

// The same densities at another origin give the same mesh, moved by the origin.
TEST_P(mesh_ChunkSeams, meshMovesWithTheOrigin) {
    const glm::ivec3 origin = GetParam();
    const auto shape = straddlingShape(glm::ivec3(0));
    auto relative = [&](glm::vec3 p) { return shape(p - glm::vec3(origin)); };
    const Mesh atZero = meshSurfaceNets(makeGrid({0, 0, 0}, kSize, 16, shape), 0.5f);
    const Mesh moved = meshSurfaceNets(makeGrid(origin, kSize, 16, relative), 0.5f);
    EXPECT_EQ(moved.triangles, atZero.triangles);
    ASSERT_EQ(moved.positions.size(), atZero.positions.size());
    // Gradient normals are the same bits; the few that follow their triangles instead
    // (orientNormalsToFaces) come from the positions, which round differently far from zero.
    size_t rederived = 0;
    for (size_t v = 0; v < moved.normals.size(); ++v) {
        if (moved.normals[v] == atZero.normals[v]) continue;
        ++rederived;
        EXPECT_GT(glm::dot(moved.normals[v], atZero.normals[v]), 0.99f) << "vertex " << v;
    }
    EXPECT_LT(rederived, moved.normals.size() / 50);
    // Far from zero a float keeps about 1/128 voxel of precision.
    for (size_t v = 0; v < moved.positions.size(); ++v)
        for (int a = 0; a < 3; ++a) ASSERT_NEAR(moved.positions[v][a] - float(origin[a]), atZero.positions[v][a], 1.0f / 64.0f);
}

std::string originName(const testing::TestParamInfo<glm::ivec3>& info) {
    const char* names[] = {"zero", "negative", "far"};
    return names[info.index];
}

INSTANTIATE_TEST_SUITE_P(origins, mesh_ChunkSeams,
                         testing::Values(glm::ivec3(0, 0, 0), glm::ivec3(-37, -5, -100), glm::ivec3(100003, 7, -65541)),
                         originName);

} // namespace chunk_seam_test
} // namespace voxc
