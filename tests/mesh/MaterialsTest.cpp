// Mesh materials against a brute-force reading of the grid, and skipping of uniform chunks.
#include "TestGrids.h"
#include "voxc/mesh/SurfaceNets.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <map>
#include <random>

namespace voxc {
namespace materials_test {

using test::makeGrid;
using test::paintMaterials;

// Random 0/1 densities and materials 0..4: crossings sit at edge midpoints, so floor(position)
// is the vertex's cell (a vertex never reaches its cell's high faces).
ChunkedGrid randomBlocks(glm::ivec3 origin, glm::ivec3 size, int32_t chunkSize, uint32_t seed) {
    std::mt19937 random(seed);
    std::vector<float> densities(size_t(size.x * size.y * size.z));
    std::vector<uint8_t> materials(densities.size());
    for (size_t i = 0; i < densities.size(); ++i) {
        densities[i] = random() % 5 < 2 ? 1.0f : 0.0f;
        materials[i] = uint8_t(random() % 5);
    }
    auto index = [&](glm::ivec3 world) {
        const glm::ivec3 p = world - origin;
        return size_t(p.x) + size_t(size.x) * (size_t(p.y) + size_t(size.y) * size_t(p.z));
    };
    ChunkedGrid grid = makeGrid(origin, size, chunkSize, [&](glm::vec3 p) { return densities[index(glm::ivec3(p))]; });
    paintMaterials(grid, [&](glm::ivec3 p) { return materials[index(p)]; });
    return grid;
}

struct Voxel {
    bool solid;
    uint8_t material;
};

Voxel voxelAt(const ChunkedGrid& grid, glm::ivec3 world) {
    const glm::ivec3 local = world - grid.layout().gridOrigin;
    if (glm::any(glm::lessThan(local, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(local, grid.layout().gridSize)))
        return {false, kMaterialNone};
    return {grid.at(local) > 0.5f, grid.materialAt(local)};
}

uint8_t expectedVertexMaterial(const ChunkedGrid& grid, glm::ivec3 cell) {
    std::map<uint8_t, int> votes;
    for (int i = 0; i < 8; ++i) {
        const Voxel voxel = voxelAt(grid, cell + glm::ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
        if (voxel.solid) ++votes[voxel.material];
    }
    uint8_t best = 0;
    int bestVotes = 0;
    for (const auto& [material, count] : votes) // ascending ids, so a tie keeps the lowest
        if (count > bestVotes) best = material, bestVotes = count;
    return best;
}

// A triangle's three cells surround one grid edge: they share the edge's axis coordinate and the
// edge starts at their componentwise maximum.
uint8_t expectedTriangleMaterial(const ChunkedGrid& grid, const glm::ivec3 (&cells)[3]) {
    int axis = -1;
    for (int a = 0; a < 3; ++a)
        if (cells[0][a] == cells[1][a] && cells[1][a] == cells[2][a]) axis = a;
    EXPECT_GE(axis, 0);
    const glm::ivec3 start = glm::max(cells[0], glm::max(cells[1], cells[2]));
    glm::ivec3 end = start;
    end[axis] += 1;
    const Voxel a = voxelAt(grid, start), b = voxelAt(grid, end);
    EXPECT_NE(a.solid, b.solid);
    return a.solid ? a.material : b.material;
}

TEST(mesh_Materials, matchBruteForceOnRandomBlocks) {
    const ChunkedGrid grid = randomBlocks({-3, 2, 5}, {14, 11, 9}, 8, 17);
    const Mesh mesh = meshSurfaceNets(grid, 0.5f);
    ASSERT_EQ(mesh.vertexMaterials.size(), mesh.positions.size());
    ASSERT_EQ(mesh.triangleMaterials.size() * 3, mesh.triangles.size());
    ASSERT_GT(mesh.triangles.size(), 300u);
    std::vector<glm::ivec3> cellOf(mesh.positions.size());
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        cellOf[v] = glm::ivec3(glm::floor(mesh.positions[v]));
        EXPECT_EQ(mesh.vertexMaterials[v], expectedVertexMaterial(grid, cellOf[v])) << "vertex " << v;
    }
    std::map<uint8_t, size_t> used;
    for (size_t t = 0; t < mesh.triangleMaterials.size(); ++t) {
        const glm::ivec3 cells[3] = {cellOf[mesh.triangles[t * 3]], cellOf[mesh.triangles[t * 3 + 1]], cellOf[mesh.triangles[t * 3 + 2]]};
        EXPECT_EQ(mesh.triangleMaterials[t], expectedTriangleMaterial(grid, cells)) << "triangle " << t;
        ++used[mesh.triangleMaterials[t]];
    }
    EXPECT_EQ(used.size(), 5u); // every material shows
}

// Two solid voxels side by side: cells holding both corners tie and take the lower id.
TEST(mesh_Materials, tieGoesToTheLowestId) {
    ChunkedGrid grid = makeGrid({0, 0, 0}, {4, 3, 3}, 8, [](glm::vec3 p) {
        return p.y == 1 && p.z == 1 && (p.x == 1 || p.x == 2) ? 1.0f : 0.0f;
    });
    paintMaterials(grid, [](glm::ivec3 p) { return uint8_t(p.x == 1 ? 9 : 4); });
    const Mesh mesh = meshSurfaceNets(grid, 0.5f);
    size_t shared = 0;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const int cellX = int(std::floor(mesh.positions[v].x));
        const uint8_t expected = cellX == 0 ? 9 : 4; // cell 0 sees voxel 1 only, cell 1 both, cell 2 voxel 2 only
        EXPECT_EQ(mesh.vertexMaterials[v], expected) << "vertex at x " << mesh.positions[v].x;
        shared += cellX == 1;
    }
    EXPECT_EQ(shared, 4u);
    // Each voxel shows five faces, two triangles each, in its own material.
    EXPECT_EQ(std::count(mesh.triangleMaterials.begin(), mesh.triangleMaterials.end(), uint8_t(9)), 10);
    EXPECT_EQ(std::count(mesh.triangleMaterials.begin(), mesh.triangleMaterials.end(), uint8_t(4)), 10);
    EXPECT_EQ(mesh.triangleMaterials.size(), 20u);
}

TEST(mesh_Materials, allNoneWithoutMaterials) {
    const Mesh mesh = meshSurfaceNets(makeGrid({0, 0, 0}, {12, 12, 12}, 8, test::coneBall({6, 6, 6}, 7)), 0.5f);
    ASSERT_FALSE(mesh.triangles.empty());
    EXPECT_EQ(mesh.vertexMaterials, std::vector<uint8_t>(mesh.positions.size(), kMaterialNone));
    EXPECT_EQ(mesh.triangleMaterials, std::vector<uint8_t>(mesh.triangles.size() / 3, kMaterialNone));
}

TEST(mesh_Materials, identicalForEveryChunkSize) {
    const Mesh reference = meshSurfaceNets(randomBlocks({-37, -5, -100}, {40, 21, 35}, 8, 3), 0.5f);
    for (int32_t chunkSize : {16, 32, 64}) {
        const Mesh mesh = meshSurfaceNets(randomBlocks({-37, -5, -100}, {40, 21, 35}, chunkSize, 3), 0.5f);
        EXPECT_EQ(mesh.vertexMaterials, reference.vertexMaterials) << "chunk size " << chunkSize;
        EXPECT_EQ(mesh.triangleMaterials, reference.triangleMaterials) << "chunk size " << chunkSize;
        EXPECT_EQ(mesh.triangles, reference.triangles) << "chunk size " << chunkSize;
    }
}

void expectSameMesh(const Mesh& a, const Mesh& b) {
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.vertexMaterials, b.vertexMaterials);
    EXPECT_EQ(a.triangleMaterials, b.triangleMaterials);
}

// Terrain below y = 20 with a ball: the deep rock and the high air are whole chunks.
TEST(mesh_SkipChunks, skippingUniformChunksNeverChangesTheMesh) {
    const auto ball = test::coneBall({30.5f, 26.2f, 33.7f}, 14.0f);
    auto terrain = [&](glm::vec3 p) { return std::max(p.y < 20.0f + 3.0f * std::sin(p.x * 0.2f) ? 1.0f : 0.0f, ball(p)); };
    for (glm::ivec3 origin : {glm::ivec3(0), glm::ivec3(-37, -5, -100)}) {
        ChunkedGrid grid = makeGrid(origin, {64, 64, 64}, 8, [&](glm::vec3 p) { return terrain(p - glm::vec3(origin)); });
        paintMaterials(grid, [](glm::ivec3 p) { return uint8_t(1 + (p.x & 3)); });
        MeshStats skipped, full;
        const Mesh withSkipping = meshSurfaceNets(grid, MeshOptions{}, &skipped);
        const Mesh withoutSkipping = meshSurfaceNets(grid, MeshOptions{.skipUniformChunks = false}, &full);
        ASSERT_GT(withSkipping.triangles.size(), 1000u);
        expectSameMesh(withSkipping, withoutSkipping);
        expectSameMesh(withSkipping, meshSurfaceNets(grid, 0.5f));
        EXPECT_EQ(skipped.chunks, full.chunks);
        EXPECT_EQ(full.skippedChunks, 0u);
        // Cells reach one voxel below the grid, so 9 chunk layers per axis hold cells.
        EXPECT_EQ(skipped.chunks, 9u * 9u * 9u);
        EXPECT_GT(skipped.skippedChunks, skipped.chunks / 3);
        EXPECT_LT(skipped.skippedChunks, skipped.chunks);
    }
}

TEST(mesh_SkipChunks, emptyGridSkipsEveryChunkAndSolidGridOnlyItsInterior) {
    MeshStats stats;
    EXPECT_TRUE(meshSurfaceNets(makeGrid({0, 0, 0}, {32, 32, 32}, 8, [](glm::vec3) { return 0.0f; }), {}, &stats).triangles.empty());
    EXPECT_EQ(stats.chunks, 5u * 5u * 5u);
    EXPECT_EQ(stats.skippedChunks, stats.chunks);

    const ChunkedGrid solid = makeGrid({0, 0, 0}, {32, 32, 32}, 8, [](glm::vec3) { return 1.0f; });
    const Mesh mesh = meshSurfaceNets(solid, {}, &stats);
    // Chunk k reads voxels 8k..8k+8: chunks -1 and 3 on an axis also read the air outside the
    // grid, so the 3x3x3 chunks 0..2 are uniform.
    EXPECT_EQ(stats.skippedChunks, 27u);
    expectSameMesh(mesh, meshSurfaceNets(solid, MeshOptions{.skipUniformChunks = false}));
}

} // namespace materials_test
} // namespace voxc
