// Meshing a grid made outside voxc that holds NaN, infinities or densities near the float
// limits: a non-finite density reads as 0 (docs/language.md, "Non-finite values"), so every
// vertex and normal is finite and the surface stays closed.
#include "TestGrids.h"
#include "voxc/mesh/SurfaceNets.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>

namespace voxc {
namespace non_finite_mesh_test {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// A ball of solid 1 in air 0, with `special` written into every third voxel of a slab through
// its middle (some inside the ball, some in the air around it).
ChunkedGrid ballWith(float special) {
    ChunkedGrid grid = test::makeGrid({-3, 0, 5}, {20, 18, 16}, 8, test::coneBall({7, 9, 13}, 7.0f));
    for (int z = 0; z < 16; ++z)
        for (int y = 7; y < 11; ++y)
            for (int x = 0; x < 20; ++x)
                if ((x + y + z) % 3 == 0) grid.at({x, y, z}) = special;
    return grid;
}

void expectFiniteAndClosed(const Mesh& mesh) {
    ASSERT_FALSE(mesh.positions.empty());
    for (const glm::vec3& p : mesh.positions) EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (const glm::vec3& n : mesh.normals) EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
    const MeshTopology topology = analyzeTopology(mesh);
    EXPECT_TRUE(topology.closed()) << topology.boundaryEdges << " boundary edges";
    EXPECT_EQ(topology.duplicateTriangles, 0u);
}

TEST(mesh_NonFinite, NonFiniteDensitiesMeshAsZero) {
    for (float special : {kNaN, -kNaN, kInf, -kInf}) {
        SCOPED_TRACE(special);
        const Mesh mesh = meshSurfaceNets(ballWith(special), 0.5f);
        expectFiniteAndClosed(mesh);
        const Mesh zero = meshSurfaceNets(ballWith(0.0f), 0.5f);
        EXPECT_EQ(mesh.positions, zero.positions);
        EXPECT_EQ(mesh.normals, zero.normals);
        EXPECT_EQ(mesh.triangles, zero.triangles);
    }
}

// Neighbouring densities of +-FLT_MAX overflow every float difference the mesher takes.
TEST(mesh_NonFinite, DensitiesAtTheFloatLimitsGiveFiniteVertices) {
    for (float special : {FLT_MAX, -FLT_MAX}) {
        SCOPED_TRACE(special);
        ChunkedGrid grid = ballWith(special);
        for (int x = 0; x < 20; x += 2) grid.at({x, 4, 4}) = -special;
        expectFiniteAndClosed(meshSurfaceNets(grid, 0.5f));
    }
    // An iso near the float limit too.
    ChunkedGrid grid = ballWith(FLT_MAX);
    for (int x = 0; x < 20; x += 2) grid.at({x, 4, 4}) = -FLT_MAX;
    expectFiniteAndClosed(meshSurfaceNets(grid, FLT_MAX / 2));
}

} // namespace non_finite_mesh_test
} // namespace voxc
