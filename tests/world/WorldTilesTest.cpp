// voxc world's tiles (voxc/world/Tiles.h): written, read back from their OpenVDB files and put
// together, they equal the whole world's run; their meshes welded by position are the whole
// world's mesh, watertight, and two neighbours share every vertex on their common face; a run
// stopped after some tiles resumes, keeping exactly the tiles whose files still hash as listed,
// and ends with the same voxels.
#include "GridCompare.h"
#include "voxc/check/Check.h"
#include "voxc/mesh/Export.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Region.h"
#include "voxc/world/Tiles.h"
#include "voxc/world/VdbTile.h"

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <algorithm>
#include <array>
#include <bit>
#include <glm/common.hpp>
#include <gtest/gtest.h>
#include <map>
#include <set>

namespace voxc {
namespace {

namespace fs = std::filesystem;

struct Stop {};

class WorldTiles : public ::testing::Test {
protected:
    void SetUp() override {
        CheckResult checked = checkFile(fmt::format("{}/examples/scene.vox", VOXC_SOURCE_DIR));
        ASSERT_FALSE(checked.hasErrors());
        program = std::move(*checked.program);
        program.world.origin += glm::ivec3(-40, -3, 17);
        directory = fs::temp_directory_path() / fmt::format("voxc_world_tiles_{}", ::getpid());
        fs::remove_all(directory);
    }
    void TearDown() override { fs::remove_all(directory); }

    world::WorldOptions options(int* computed) const {
        world::WorldOptions o;
        o.directory = directory.string();
        o.tile = 40;
        o.sourceText = "scene";
        o.meshFormat = "ply";
        o.run = [computed](const Program& region) {
            ++*computed;
            return interpret(region);
        };
        return o;
    }

    // The first of the first `count` tiles that has a mesh file, (1,0,0) excepted.
    glm::ivec3 tileWithMesh(int count) const {
        const glm::ivec3 tiles = (program.world.size + 39) / 40;
        for (int index = 0; index < count; ++index) {
            const glm::ivec3 tile(index % tiles.x, index / tiles.x % tiles.y, index / (tiles.x * tiles.y));
            if (tile != glm::ivec3(1, 0, 0) && fs::exists(directory / world::tileMeshFileName(tile, "ply"))) return tile;
        }
        ADD_FAILURE() << "no tile with a mesh";
        return {};
    }

    // Every tile read back and put in place.
    DenseGrid readBack() const {
        const glm::ivec3 size = program.world.size;
        DenseGrid all(size);
        const glm::ivec3 tiles = (size + 39) / 40;
        for (int k = 0; k < tiles.z; ++k)
            for (int j = 0; j < tiles.y; ++j)
                for (int i = 0; i < tiles.x; ++i) {
                    const glm::ivec3 min = glm::ivec3(i, j, k) * 40, max = glm::min(min + 40, size);
                    const DenseGrid tile = world::readTileVdb((directory / world::tileFileName({i, j, k})).string(),
                                                              program.world.origin + min, max - min);
                    for (int z = min.z; z < max.z; ++z)
                        for (int y = min.y; y < max.y; ++y)
                            for (int x = min.x; x < max.x; ++x) {
                                all.at({x, y, z}) = tile.at(glm::ivec3(x, y, z) - min);
                                all.materialAt({x, y, z}) = tile.materialAt(glm::ivec3(x, y, z) - min);
                            }
                }
        return all;
    }

    Program program;
    fs::path directory;
};

// A vertex position's bits: welding joins exactly equal positions.
using PositionBits = std::array<uint32_t, 3>;
PositionBits bitsOf(glm::vec3 p) { return {std::bit_cast<uint32_t>(p.x), std::bit_cast<uint32_t>(p.y), std::bit_cast<uint32_t>(p.z)}; }

// Meshes joined at equal positions and normals: one vertex per position and normal (a position
// seen again with the same normal must carry the same material; with another normal it is a copy
// made for its normals, Mesh::normalSplits), triangles in the order given. `point` maps each
// vertex to the first at its position, for the topology.
struct Welded {
    Mesh mesh;
    std::map<std::pair<PositionBits, PositionBits>, uint32_t> vertexAt;
    std::map<PositionBits, uint32_t> pointAt;
    std::vector<uint32_t> point;
    size_t conflicts = 0; // repeated positions and normals with another material
};
void weld(Welded& welded, const Mesh& part) {
    std::vector<uint32_t> index(part.positions.size());
    for (size_t v = 0; v < part.positions.size(); ++v) {
        const PositionBits position = bitsOf(part.positions[v]);
        const auto [it, added] = welded.vertexAt.try_emplace({position, bitsOf(part.normals[v])}, uint32_t(welded.mesh.positions.size()));
        index[v] = it->second;
        if (added) {
            welded.point.push_back(welded.pointAt.try_emplace(position, it->second).first->second);
            welded.mesh.positions.push_back(part.positions[v]);
            welded.mesh.normals.push_back(part.normals[v]);
            welded.mesh.vertexMaterials.push_back(part.vertexMaterials[v]);
        } else if (welded.mesh.vertexMaterials[it->second] != part.vertexMaterials[v]) {
            ++welded.conflicts;
        }
    }
    for (uint32_t corner : part.triangles) welded.mesh.triangles.push_back(index[corner]);
    welded.mesh.triangleMaterials.insert(welded.mesh.triangleMaterials.end(), part.triangleMaterials.begin(),
                                         part.triangleMaterials.end());
}
// The welded mesh with every vertex replaced by the first at its position.
Mesh byPoint(const Welded& welded) {
    Mesh mesh = welded.mesh;
    for (uint32_t& corner : mesh.triangles) corner = welded.point[corner];
    return mesh;
}

// A mesh as sets, independent of vertex numbering and triangle order: vertices (position, normal,
// material) and triangles (their corners' positions in winding order, and material).
struct MeshContent {
    std::set<std::tuple<PositionBits, PositionBits, uint8_t>> vertices;
    std::multiset<std::tuple<PositionBits, PositionBits, PositionBits, uint8_t>> triangles;
    bool operator==(const MeshContent&) const = default;
};
MeshContent contentOf(const Mesh& mesh) {
    MeshContent content;
    for (size_t v = 0; v < mesh.positions.size(); ++v)
        content.vertices.emplace(bitsOf(mesh.positions[v]), bitsOf(mesh.normals[v]), mesh.vertexMaterials[v]);
    for (size_t t = 0; t < mesh.triangleMaterials.size(); ++t)
        content.triangles.emplace(bitsOf(mesh.positions[mesh.triangles[3 * t]]), bitsOf(mesh.positions[mesh.triangles[3 * t + 1]]),
                                  bitsOf(mesh.positions[mesh.triangles[3 * t + 2]]), mesh.triangleMaterials[t]);
    return content;
}

TEST_F(WorldTiles, ReadBackEqualTheWholeWorld) {
    int computed = 0;
    const world::WorldSummary summary = world::writeWorld(program, options(&computed));
    EXPECT_EQ(summary.tiles, 3 * 2 * 3);
    EXPECT_EQ(computed, 18);
    EXPECT_EQ(test::countVoxelDifferences(interpret(program), readBack()), 0u);
}

TEST_F(WorldTiles, TileMeshesWeldIntoTheWholeWorldsMesh) {
    int computed = 0;
    world::writeWorld(program, options(&computed));
    const glm::ivec3 tiles = (program.world.size + 39) / 40;
    Welded all;
    std::map<glm::ivec3, Mesh, decltype([](glm::ivec3 a, glm::ivec3 b) {
                 return std::tuple(a.z, a.y, a.x) < std::tuple(b.z, b.y, b.x);
             })>
        meshes;
    for (int k = 0; k < tiles.z; ++k)
        for (int j = 0; j < tiles.y; ++j)
            for (int i = 0; i < tiles.x; ++i) {
                const fs::path path = directory / world::tileMeshFileName({i, j, k}, "ply");
                if (!fs::exists(path)) continue; // a tile without triangles
                weld(all, meshes[{i, j, k}] = readPly(path.string()));
            }
    ASSERT_GE(meshes.size(), 9u); // the ground crosses every column of tiles
    const DenseGrid voxels = interpret(program);
    const Mesh whole = meshMarchingCubes(
        ChunkedGrid::fromDense(voxels, ChunkLayout::make(program.world.origin, program.world.size, program.world.chunkSize)),
        MeshOptions{});
    EXPECT_EQ(all.conflicts, 0u);
    EXPECT_EQ(all.mesh.positions.size(), whole.positions.size());
    EXPECT_EQ(all.mesh.triangles.size(), whole.triangles.size());
    EXPECT_TRUE(contentOf(all.mesh) == contentOf(whole));
    const MeshTopology topology = analyzeTopology(byPoint(all));
    EXPECT_TRUE(topology.watertight()) << topology.boundaryEdges << " boundary edges";
    EXPECT_EQ(topology.misorientedEdges, 0u);

    // Two neighbours alone: every vertex either has on their common face (x = 40 in the grid) the
    // other has too, with the same bits, so the weld leaves no open edge on that face.
    const Mesh& left = meshes.at({0, 0, 0});
    const Mesh& right = meshes.at({1, 0, 0});
    const float face = float(program.world.origin.x + 40);
    Welded pair;
    weld(pair, left);
    const size_t leftOnly = pair.mesh.positions.size();
    weld(pair, right);
    size_t onFace = 0, shared = 0;
    for (const glm::vec3& p : right.positions)
        if (p.x == face) {
            ++onFace;
            shared += pair.pointAt.at(bitsOf(p)) < leftOnly;
        }
    EXPECT_GT(onFace, 20u);
    EXPECT_EQ(shared, onFace);
    EXPECT_EQ(pair.conflicts, 0u);
    size_t openOnFace = 0;
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    const Mesh pairPoints = byPoint(pair);
    for (size_t t = 0; t < pairPoints.triangles.size(); t += 3)
        for (size_t e = 0; e < 3; ++e) {
            const uint32_t a = pairPoints.triangles[t + e], b = pairPoints.triangles[t + (e + 1) % 3];
            ++uses[std::minmax(a, b)];
        }
    for (const auto& [edge, count] : uses)
        openOnFace += count == 1 && pair.mesh.positions[edge.first].x == face && pair.mesh.positions[edge.second].x == face;
    EXPECT_EQ(openOnFace, 0u);
}

TEST_F(WorldTiles, AStoppedRunResumes) {
    int computed = 0;
    world::WorldOptions first = options(&computed);
    first.progress = [](const world::TileProgress& progress) {
        if (progress.done == 7) throw Stop{};
    };
    EXPECT_THROW(world::writeWorld(program, first), Stop);
    EXPECT_EQ(computed, 7);
    // A tile whose file changed since it was listed is computed again.
    {
        std::fstream file(directory / world::tileFileName({1, 0, 0}), std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(40);
        file.put('\x5a');
    }
    // So is one whose mesh file is gone.
    const glm::ivec3 meshed = tileWithMesh(6);
    fs::remove(directory / world::tileMeshFileName(meshed, "ply"));
    computed = 0;
    const world::WorldSummary summary = world::writeWorld(program, options(&computed));
    EXPECT_EQ(summary.kept, 5);
    EXPECT_EQ(computed, 18 - 5);
    EXPECT_TRUE(fs::exists(directory / world::tileMeshFileName(meshed, "ply")));
    EXPECT_EQ(test::countVoxelDifferences(interpret(program), readBack()), 0u);
    computed = 0;
    EXPECT_EQ(world::writeWorld(program, options(&computed)).kept, 18); // all up to date
    EXPECT_EQ(computed, 0);
}

TEST_F(WorldTiles, AnotherWorldsDirectoryIsRefused) {
    int computed = 0;
    world::WorldOptions o = options(&computed);
    o.progress = [](const world::TileProgress&) { throw Stop{}; };
    EXPECT_THROW(world::writeWorld(program, o), Stop);
    o.progress = {};
    o.tile = 32;
    EXPECT_THROW(world::writeWorld(program, o), UserError);
}

} // namespace
} // namespace voxc
