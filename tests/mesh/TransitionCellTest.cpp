// The derived transition cells, exhaustively where the case count allows: every sign pattern of a
// coarse cell's 13 samples against a finer chunk across one face, of its 9 samples against a finer
// chunk along one edge, and samples of the two- and three-face corner shapes, each embedded in air
// and in solid, meshes closed, manifold and facing outwards together with the chunks around it.
#include "TestGrids.h"
#include "voxc/mesh/Lod.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/mesh/MeshQuality.h"
#include "voxc/mesh/TransitionCells.h"

#include <functional>
#include <gtest/gtest.h>
#include <random>

namespace voxc {
namespace transition_cell_test {

namespace tc = transition_cells;

// A 7^3 grid (world -2..4) in chunks of 2 voxels; chunks where `fine(chunk)` holds are at level 0,
// the others at level 1. The coarse cell under test is [0,2]^3 (chunk (0,0,0)).
struct Embedding {
    std::function<bool(glm::ivec3)> fine;
    uint32_t points; // the cell's samples this layout gives it
};

LodLayout layoutOf(const ChunkLayout& grid, const std::function<bool(glm::ivec3)>& fine) {
    LodLayout layout = LodLayout::uniform(grid, 1);
    for (int z = 0; z < layout.chunkCount.z; ++z)
        for (int y = 0; y < layout.chunkCount.y; ++y)
            for (int x = 0; x < layout.chunkCount.x; ++x) {
                const glm::ivec3 chunk = layout.firstChunk + glm::ivec3(x, y, z);
                if (fine(chunk)) layout.setLevel(chunk, 0);
            }
    return layout;
}

uint32_t pointsOnFaces(std::initializer_list<int> faces) {
    uint32_t points = tc::kCornerPoints;
    for (int face : faces) {
        const int axis = face / 2;
        for (int p = 0; p < tc::kPoints; ++p)
            if (tc::pointOffset(p)[axis] == 2 * (face % 2)) points |= 1u << p;
    }
    return points;
}

// Meshes the embedding with the cell's samples set from `pattern` (bit i = the i-th sample of
// `points`, ascending) and every other voxel `fill`.
MeshQuality meshPattern(const Embedding& e, uint32_t pattern, float fill, LodStats* stats = nullptr) {
    ChunkedGrid grid(ChunkLayout::make({-2, -2, -2}, {7, 7, 7}, 2));
    for (float& d : grid.data()) d = fill;
    int bit = 0;
    for (int p = 0; p < tc::kPoints; ++p)
        if ((e.points >> p) & 1u) grid.at(tc::pointOffset(p) + 2) = (pattern >> bit++) & 1u ? 1.0f : 0.0f;
    const LodPyramid pyramid(grid, 1);
    const Mesh mesh = meshLod(pyramid, layoutOf(grid.layout(), e.fine), MeshOptions{}, stats);
    const MeshQuality q = measureMeshQuality(mesh);
    EXPECT_EQ(analyzeTopology(mesh).duplicateTriangles, 0u) << pattern;
    return q;
}

void expectPatternsManifold(const Embedding& e, size_t samples /* 0: every pattern */) {
    const int bits = std::popcount(e.points);
    const uint32_t all = 1u << bits;
    std::mt19937 random(17);
    const size_t count = samples == 0 ? all : samples;
    for (size_t i = 0; i < count; ++i) {
        const uint32_t pattern = samples == 0 ? uint32_t(i) : uint32_t(random()) % all;
        for (float fill : {0.0f, 1.0f}) {
            const MeshQuality q = meshPattern(e, pattern, fill);
            ASSERT_TRUE(q.manifold()) << "pattern " << pattern << " fill " << fill << ": " << describeMeshQuality(q);
            ASSERT_EQ(q.zeroAreaTriangles + q.repeatedIndexTriangles, 0u) << "pattern " << pattern << " fill " << fill;
            if (pattern != 0 || fill != 0.0f) { ASSERT_GT(q.signedVolume, 0.0) << "pattern " << pattern << " fill " << fill; }
        }
    }
}

TEST(mesh_TransitionCells, shapesAreValidatedAndRegularCellsMatchTheTable) {
    EXPECT_TRUE(tc::validShape(tc::kCornerPoints));
    EXPECT_FALSE(tc::validShape(tc::kCornerPoints & ~1u));                          // a corner missing
    EXPECT_FALSE(tc::validShape(tc::kCornerPoints | 1u << 13));                     // the cell's centre
    EXPECT_FALSE(tc::validShape(tc::kCornerPoints | 1u << tc::pointAt({2, 1, 1}))); // a face centre without its edges
    EXPECT_TRUE(tc::validShape(pointsOnFaces({1})));
    EXPECT_EQ(std::popcount(pointsOnFaces({1})), 13);
    // On a regular cell the facet rule gives the regular table's cuts: the same crossed edges.
    for (unsigned mask = 0; mask < 256; ++mask) {
        uint32_t solid = 0;
        for (int c = 0; c < 8; ++c)
            if ((mask >> c) & 1u) solid |= 1u << tc::pointAt(2 * marching_cubes::cornerOffset(c));
        const tc::CellTriangles derived = tc::deriveCell(tc::kCornerPoints, solid);
        EXPECT_EQ(derived.triangleCount(), size_t(marching_cubes::caseTable()[mask].triangleCount)) << mask;
    }
}

// The transition cell proper: 13 samples, the finer chunk across its +x face.
TEST(mesh_TransitionCells, everyFaceTransitionCaseIsClosedManifoldAndOutward) {
    const Embedding e{[](glm::ivec3 c) { return c.x >= 1; }, pointsOnFaces({1})};
    LodStats stats;
    meshPattern(e, 0, 1.0f, &stats);
    EXPECT_GT(stats.transitionFaces, 0u);
    expectPatternsManifold(e, 0);
}

// A finer chunk only along the cell's edge x = 2, z = 2: one split edge, 9 samples.
TEST(mesh_TransitionCells, everySplitEdgeCaseIsClosedManifoldAndOutward) {
    const Embedding e{[](glm::ivec3 c) { return c.x >= 1 && c.z >= 1; }, tc::kCornerPoints | 1u << tc::pointAt({2, 1, 2})};
    expectPatternsManifold(e, 0);
}

// Finer chunks across two faces (17 samples) and three faces (20 samples): sampled.
TEST(mesh_TransitionCells, twoFaceCornerCasesAreClosedManifoldAndOutward) {
    const Embedding e{[](glm::ivec3 c) { return c.x >= 1 || c.z >= 1; }, pointsOnFaces({1, 5})};
    EXPECT_EQ(std::popcount(e.points), 17);
    expectPatternsManifold(e, 1500);
}

TEST(mesh_TransitionCells, threeFaceCornerCasesAreClosedManifoldAndOutward) {
    const Embedding e{[](glm::ivec3 c) { return c.x >= 1 || c.y >= 1 || c.z >= 1; }, pointsOnFaces({1, 3, 5})};
    EXPECT_EQ(std::popcount(e.points), 20);
    expectPatternsManifold(e, 1500);
}

} // namespace transition_cell_test
} // namespace voxc
