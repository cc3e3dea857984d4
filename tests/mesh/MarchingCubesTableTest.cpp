// The derived case table, exhaustively (spec M1-M3): every single-cell case and every sign
// pattern of two face-adjacent cells, embedded in air and in a solid shell, meshes closed,
// manifold and facing outwards; crossings interpolate from the edge's lower sample.
#include "TestGrids.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/mesh/MeshQuality.h"

#include <gtest/gtest.h>
#include <set>

namespace voxc {
namespace marching_cubes_table_test {

using marching_cubes::caseTable;
using marching_cubes::cornerOffset;

// Samples of a box of `size` voxels at the origin: `pattern` bit i sets the i-th voxel (x fastest)
// of the `inner` box at `at` to 1; the rest of the grid is `fill`.
ChunkedGrid patternGrid(glm::ivec3 size, glm::ivec3 at, glm::ivec3 inner, unsigned pattern, float fill) {
    ChunkedGrid grid(ChunkLayout::make({0, 0, 0}, size, 8));
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) grid.at({x, y, z}) = fill;
    int bit = 0;
    for (int z = 0; z < inner.z; ++z)
        for (int y = 0; y < inner.y; ++y)
            for (int x = 0; x < inner.x; ++x, ++bit) grid.at(at + glm::ivec3(x, y, z)) = (pattern >> bit) & 1u ? 1.0f : 0.0f;
    return grid;
}

// Meshes every pattern of an `inner` box in air (grid = the box) and inside a solid shell one
// voxel thick (the grid's own outside is air, so that shell is closed too).
void expectEveryPatternManifold(glm::ivec3 inner) {
    const int bits = inner.x * inner.y * inner.z;
    size_t checked = 0;
    for (unsigned pattern = 0; pattern < (1u << bits); ++pattern)
        for (bool shell : {false, true}) {
            const ChunkedGrid grid = shell ? patternGrid(inner + 2, glm::ivec3(1), inner, pattern, 1.0f)
                                           : patternGrid(inner, glm::ivec3(0), inner, pattern, 0.0f);
            const Mesh mesh = meshMarchingCubes(grid, MeshOptions{});
            const MeshQuality q = measureMeshQuality(mesh);
            ASSERT_TRUE(q.manifold()) << "pattern " << pattern << (shell ? " in a shell: " : " in air: ") << describeMeshQuality(q);
            ASSERT_EQ(q.zeroAreaTriangles + q.repeatedIndexTriangles, 0u) << "pattern " << pattern;
            ASSERT_EQ(analyzeTopology(mesh).duplicateTriangles, 0u) << "pattern " << pattern;
            if (pattern != 0 || shell) ASSERT_GT(q.signedVolume, 0.0) << "pattern " << pattern;
            ++checked;
        }
    EXPECT_EQ(checked, size_t(2) << bits);
}

TEST(mesh_McTable, everyCaseHasValidTriangles) {
    size_t most = 0;
    for (unsigned mask = 0; mask < 256; ++mask) {
        const marching_cubes::CellCase& c = caseTable()[mask];
        EXPECT_EQ(c.triangleCount == 0, mask == 0 || mask == 255) << mask;
        most = std::max<size_t>(most, c.triangleCount);
        for (int t = 0; t < c.triangleCount; ++t) {
            std::set<int> edges;
            for (int k = 0; k < 3; ++k) {
                const int e = c.edges[size_t(t * 3 + k)];
                ASSERT_LT(e, 12);
                const auto corners = marching_cubes::edgeCorners(e);
                // Only crossed edges: one solid and one air corner.
                EXPECT_NE((mask >> corners[0]) & 1u, (mask >> corners[1]) & 1u) << "case " << mask << " edge " << e;
                edges.insert(e);
            }
            EXPECT_EQ(edges.size(), 3u) << "case " << mask;
        }
    }
    EXPECT_LE(most, size_t(marching_cubes::kMaxTrianglesPerCell));
}

TEST(mesh_McTable, edgesRunAlongTheirAxisFromTheLowerCorner) {
    for (int e = 0; e < 12; ++e) {
        const auto c = marching_cubes::edgeCorners(e);
        const glm::ivec3 step = cornerOffset(c[1]) - cornerOffset(c[0]);
        glm::ivec3 axis(0);
        axis[marching_cubes::edgeAxis(e)] = 1;
        EXPECT_EQ(step, axis) << e;
    }
}

TEST(mesh_McTable, everySingleCellIsClosedManifoldAndOutward) { expectEveryPatternManifold({2, 2, 2}); }

TEST(mesh_McTable, everyFaceAdjacentPairAlongXIsClosedManifoldAndOutward) { expectEveryPatternManifold({3, 2, 2}); }
TEST(mesh_McTable, everyFaceAdjacentPairAlongYIsClosedManifoldAndOutward) { expectEveryPatternManifold({2, 3, 2}); }
TEST(mesh_McTable, everyFaceAdjacentPairAlongZIsClosedManifoldAndOutward) { expectEveryPatternManifold({2, 2, 3}); }

// A lone solid corner gives one triangle facing away from it (spec M2, the sign convention).
TEST(mesh_McTable, loneSolidCornerFacesAway) {
    for (int corner = 0; corner < 8; ++corner) {
        const marching_cubes::CellCase& c = caseTable()[1u << corner];
        ASSERT_EQ(c.triangleCount, 1);
        glm::vec3 p[3];
        for (int k = 0; k < 3; ++k) {
            const auto ends = marching_cubes::edgeCorners(c.edges[size_t(k)]);
            p[k] = 0.5f * glm::vec3(cornerOffset(ends[0]) + cornerOffset(ends[1]));
        }
        const glm::vec3 away = glm::vec3(0.5f) - glm::vec3(cornerOffset(corner));
        EXPECT_GT(glm::dot(glm::cross(p[1] - p[0], p[2] - p[0]), away), 0.0f) << corner;
    }
}

// Spec M3: t from the lower sample, so P = p0 + t (p1 - p0) with the base point.
TEST(mesh_McTable, crossingInterpolatesFromTheLowerSample) {
    EXPECT_EQ(marching_cubes::crossing(1.0f, 0.0f, 0.5f), 0.5f);
    EXPECT_EQ(marching_cubes::crossing(0.75f, 0.25f, 0.5f), 0.5f);
    EXPECT_EQ(marching_cubes::crossing(1.0f, 0.25f, 0.5f), 0.6666667f);
    EXPECT_EQ(marching_cubes::crossing(0.25f, 1.0f, 0.5f), 0.33333334f);
    // A sample exactly at iso is air; the crossing stays the margin away from it.
    EXPECT_EQ(marching_cubes::crossing(1.0f, 0.5f, 0.5f), 1.0f - kCrossingMargin);
    EXPECT_EQ(marching_cubes::crossing(0.5f, 1.0f, 0.5f), kCrossingMargin);
    EXPECT_EQ(marching_cubes::crossing(1.0f, 0.5f, 0.5f, 0.125f), 0.875f);
    // Far-apart samples do not overflow.
    EXPECT_EQ(marching_cubes::crossing(3e38f, -3e38f, 0.5f), 0.5f);
}

TEST(mesh_McTable, vertexSitsAtTheInterpolatedCrossing) {
    ChunkedGrid grid(ChunkLayout::make({10, -4, 7}, {2, 1, 1}, 8));
    grid.at({0, 0, 0}) = 1.0f;
    grid.at({1, 0, 0}) = 0.25f;
    const Mesh mesh = meshMarchingCubes(grid, MeshOptions{});
    bool found = false;
    for (const glm::vec3& p : mesh.positions)
        if (p.y == -4.0f && p.z == 7.0f && p.x > 10.0f && p.x < 11.0f) {
            EXPECT_EQ(p.x, 10.0f + 0.6666667f);
            found = true;
        }
    EXPECT_TRUE(found);
}

} // namespace marching_cubes_table_test
} // namespace voxc
