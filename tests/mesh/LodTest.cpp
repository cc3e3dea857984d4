// Level of detail (spec 4.3, L1-L7): decimated data, the 2:1 rule, crack-free mixed layouts checked
// by welding on exact positions and an exact T-junction predicate, transition placement, the
// geometric error per level against the ramp width, and invariance to chunk size and threads.
#include "TestGrids.h"
#include "voxc/core/Errors.h"
#include "voxc/mesh/Lod.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/mesh/MeshQuality.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <map>
#include <random>
#include <set>
#include <unordered_map>

namespace voxc {
namespace lod_test {

using test::makeGrid;

std::function<float(glm::vec3)> ramp(std::function<float(glm::vec3)> sdf, float width) {
    return [=](glm::vec3 p) { return std::clamp(0.5f - sdf(p) / width, 0.0f, 1.0f); };
}
std::function<float(glm::vec3)> sphereSdf(glm::vec3 c, float r) {
    return [=](glm::vec3 p) { return glm::length(p - c) - r; };
}

ChunkedGrid stripedNoiseGrid(glm::ivec3 origin, glm::ivec3 size, int32_t chunkSize, unsigned seed) {
    ChunkedGrid grid = test::noiseGrid(origin, size, chunkSize, seed);
    test::paintMaterials(grid, test::stripeMaterial);
    return grid;
}

template <class T> bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}
bool identical(const Mesh& a, const Mesh& b) {
    return sameBytes(a.positions, b.positions) && sameBytes(a.normals, b.normals) && sameBytes(a.triangles, b.triangles) &&
           sameBytes(a.vertexMaterials, b.vertexMaterials) && sameBytes(a.triangleMaterials, b.triangleMaterials) &&
           a.normalSplits == b.normalSplits;
}

LodLayout layoutBy(const ChunkLayout& grid, const std::function<int(glm::ivec3)>& level) {
    LodLayout layout = LodLayout::uniform(grid, 0);
    for (int z = 0; z < layout.chunkCount.z; ++z)
        for (int y = 0; y < layout.chunkCount.y; ++y)
            for (int x = 0; x < layout.chunkCount.x; ++x) {
                const glm::ivec3 chunk = layout.firstChunk + glm::ivec3(x, y, z);
                layout.setLevel(chunk, level(chunk));
            }
    return layout;
}

// The same mesh with vertices merged by their exact position bits (an independent weld: it does
// not trust the mesher's edge keys).
Mesh weldByPosition(const Mesh& mesh) {
    Mesh welded;
    std::map<std::array<uint32_t, 3>, uint32_t> index;
    std::vector<uint32_t> remap(mesh.positions.size());
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        std::array<uint32_t, 3> bits;
        std::memcpy(bits.data(), &mesh.positions[v], sizeof bits);
        const auto [it, added] = index.emplace(bits, uint32_t(welded.positions.size()));
        if (added) {
            welded.positions.push_back(mesh.positions[v]);
            welded.normals.push_back(mesh.normals[v]);
            welded.vertexMaterials.push_back(mesh.vertexMaterials[v]);
        }
        remap[v] = it->second;
    }
    for (uint32_t i : mesh.triangles) welded.triangles.push_back(remap[i]);
    welded.triangleMaterials = mesh.triangleMaterials;
    return welded;
}

// Vertices lying strictly inside an edge of a triangle they do not belong to, decided exactly:
// positions scaled by 2^40 are integers (every coordinate here is 0 or at least 2^-10 in size),
// so the collinearity cross product is exact in 128-bit integers.
std::vector<std::string> findTJunctions(const Mesh& mesh) {
    using I = __int128;
    std::vector<std::array<int64_t, 3>> p(mesh.positions.size());
    for (size_t v = 0; v < p.size(); ++v)
        for (int a = 0; a < 3; ++a) {
            const double scaled = std::ldexp(double(mesh.positions[v][a]), 40);
            EXPECT_EQ(scaled, std::floor(scaled)) << "position not on the 2^-40 lattice";
            p[v][size_t(a)] = int64_t(scaled);
        }
    std::set<std::pair<uint32_t, uint32_t>> edges;
    for (size_t t = 0; t < mesh.triangles.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = mesh.triangles[t + size_t(k)], b = mesh.triangles[t + size_t((k + 1) % 3)];
            edges.insert({std::min(a, b), std::max(a, b)});
        }
    // Vertices bucketed by voxel; an edge looks only in the voxels its bounding box covers.
    std::unordered_map<uint64_t, std::vector<uint32_t>> buckets;
    auto bucketKey = [](glm::ivec3 c) { return (uint64_t(uint32_t(c.x + 4096)) << 42) | (uint64_t(uint32_t(c.y + 4096)) << 21) | uint64_t(uint32_t(c.z + 4096)); };
    for (uint32_t v = 0; v < mesh.positions.size(); ++v) buckets[bucketKey(glm::ivec3(glm::floor(mesh.positions[v])))].push_back(v);
    std::vector<std::string> found;
    auto show = [&](uint32_t v) {
        const glm::vec3 q = mesh.positions[v];
        return "(" + std::to_string(q.x) + " " + std::to_string(q.y) + " " + std::to_string(q.z) + ")";
    };
    for (const auto& [a, b] : edges) {
        const glm::ivec3 lo(glm::floor(glm::min(mesh.positions[a], mesh.positions[b])));
        const glm::ivec3 hi(glm::floor(glm::max(mesh.positions[a], mesh.positions[b])));
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) {
                    const auto bucket = buckets.find(bucketKey({x, y, z}));
                    if (bucket == buckets.end()) continue;
                    for (uint32_t v : bucket->second) {
                        if (v == a || v == b) continue;
                        I d[3], q[3];
                        for (int i = 0; i < 3; ++i) {
                            d[i] = I(p[b][size_t(i)]) - p[a][size_t(i)];
                            q[i] = I(p[v][size_t(i)]) - p[a][size_t(i)];
                        }
                        const bool collinear = d[1] * q[2] == d[2] * q[1] && d[2] * q[0] == d[0] * q[2] && d[0] * q[1] == d[1] * q[0];
                        const I along = d[0] * q[0] + d[1] * q[1] + d[2] * q[2];
                        const I length = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                        if (collinear && along > 0 && along < length) found.push_back(show(v) + " inside " + show(a) + "-" + show(b));
                    }
                }
    }
    return found;
}

// L3's checks: closed, manifold and oriented by the mesher's weld and by an exact-position weld,
// no zero-area triangles, no T-junctions.
void expectCrackFree(const Mesh& mesh, const std::string& what) {
    const MeshQuality q = measureMeshQuality(mesh);
    EXPECT_TRUE(q.manifold()) << what << ": " << describeMeshQuality(q);
    EXPECT_EQ(q.zeroAreaTriangles + q.repeatedIndexTriangles + q.nonFiniteVertices, 0u) << what << ": " << describeMeshQuality(q);
    EXPECT_GT(q.signedVolume, 0.0) << what;
    const MeshQuality welded = measureMeshQuality(weldByPosition(mesh));
    // Only the copies made for their normals (Mesh::normalSplits) share a point with another vertex.
    EXPECT_EQ(welded.vertices, q.vertices - mesh.normalSplits.size()) << what << ": two vertices at one position";
    EXPECT_TRUE(welded.manifold()) << what << " welded by position: " << describeMeshQuality(welded);
    const std::vector<std::string> tJunctions = findTJunctions(mesh);
    EXPECT_TRUE(tJunctions.empty()) << what << ": " << tJunctions.size() << " T-junctions, first " << tJunctions.front();
}

struct Fixture {
    std::string name;
    ChunkedGrid grid;
};

std::vector<Fixture> crackFixtures(int32_t chunkSize) {
    std::vector<Fixture> fixtures;
    fixtures.push_back({"sphere w=8", makeGrid({0, 0, 0}, {64, 64, 64}, chunkSize, ramp(sphereSdf({32.4f, 30.2f, 33.7f}, 20.3f), 8.0f))});
    fixtures.push_back({"plane 24.3 w=8", makeGrid({0, 0, 0}, {64, 48, 64}, chunkSize, ramp([](glm::vec3 p) { return p.y - 24.3f; }, 8.0f))});
    fixtures.push_back({"noise", stripedNoiseGrid({-37, -5, -70}, {48, 40, 56}, chunkSize, 3)});
    return fixtures;
}

int levelsPresent(const LodLayout& layout) {
    std::set<uint8_t> levels(layout.levels.begin(), layout.levels.end());
    return int(levels.size());
}

// L1: level k's sample i is LOD0's sample 2^k i, bit for bit, also after an edit refreshed over
// its box.
TEST(mesh_Lod, decimationKeepsLodZeroSamples) {
    for (glm::ivec3 origin : {glm::ivec3(0), glm::ivec3(-37, -5, -70), glm::ivec3(1000, 17, -999)}) {
        ChunkedGrid grid = stripedNoiseGrid(origin, {37, 21, 30}, 8, 5);
        LodPyramid pyramid(grid, 3);
        auto expectDecimated = [&] {
            for (int k = 1; k <= 3; ++k) {
                const ChunkedGrid& level = *pyramid.level(k);
                const ChunkLayout& l = level.layout();
                size_t checked = 0;
                for (int z = 0; z < l.gridSize.z; ++z)
                    for (int y = 0; y < l.gridSize.y; ++y)
                        for (int x = 0; x < l.gridSize.x; ++x) {
                            const glm::ivec3 source = (l.gridOrigin + glm::ivec3(x, y, z)) * (1 << k) - origin;
                            const float coarse = level.at({x, y, z}), fine = grid.at(source);
                            ASSERT_EQ(std::memcmp(&coarse, &fine, sizeof(float)), 0);
                            ASSERT_EQ(level.materialAt({x, y, z}), grid.materialAt(source));
                            ++checked;
                        }
                // Every lattice point of the level inside the grid, none outside.
                size_t expected = 1;
                for (int a = 0; a < 3; ++a) {
                    const int step = 1 << k, lo = origin[a], hi = origin[a] + grid.layout().gridSize[a] - 1;
                    expected *= size_t(int(std::floor(double(hi) / step)) - int(std::ceil(double(lo) / step)) + 1);
                }
                EXPECT_EQ(checked, expected) << k;
            }
        };
        expectDecimated();
        // An edit of LOD0 (a carved box), refreshed over its box only.
        const glm::ivec3 first(3, 2, 5), last(20, 14, 11);
        for (int z = first.z; z <= last.z; ++z)
            for (int y = first.y; y <= last.y; ++y)
                for (int x = first.x; x <= last.x; ++x) grid.at({x, y, z}) *= 0.25f;
        pyramid.refresh(first, last);
        expectDecimated();
    }
}

// L2: touching chunks two levels apart are rejected (faces, edges and corners alike);
// balanceLod refines such a layout until it holds.
TEST(mesh_Lod, twoToOneRuleIsEnforced) {
    const ChunkedGrid grid = makeGrid({0, 0, 0}, {32, 32, 32}, 8, ramp(sphereSdf({16, 16, 16}, 9.5f), 4.0f));
    const LodPyramid pyramid(grid, 2);
    for (glm::ivec3 coarse : {glm::ivec3(2, 1, 1), glm::ivec3(2, 2, 1), glm::ivec3(2, 2, 2)}) {
        LodLayout layout = layoutBy(grid.layout(), [&](glm::ivec3 c) { return c == glm::ivec3(1, 1, 1) ? 0 : c == coarse ? 2 : 1; });
        try {
            meshLod(pyramid, layout, MeshOptions{});
            ADD_FAILURE() << "accepted level 0 touching level 2";
        } catch (const UserError& e) {
            EXPECT_NE(std::string(e.what()).find("(2:1)"), std::string::npos) << e.what();
        }
        const LodLayout before = layout;
        balanceLod(layout);
        EXPECT_NO_THROW(checkLodLayout(layout));
        EXPECT_EQ(layout.levelAt(coarse), 1);
        for (size_t i = 0; i < layout.levels.size(); ++i) EXPECT_LE(layout.levels[i], before.levels[i]); // only refined
        expectCrackFree(meshLod(pyramid, layout, MeshOptions{}), "balanced");
    }
    // A level whose cells are wider than a chunk.
    EXPECT_THROW(checkLodLayout(LodLayout::uniform(grid.layout(), 4)), UserError);
}

// L3: half-space split, 2:1 checkerboard and a three-level ring, on a sphere, a plane and noise.
TEST(mesh_Lod, mixedLayoutsAreCrackFree) {
    for (int32_t chunkSize : {8, 16}) {
        for (const Fixture& f : crackFixtures(chunkSize)) {
            const ChunkLayout& grid = f.grid.layout();
            const LodPyramid pyramid(f.grid, 2);
            const int half = (grid.gridOrigin.x + grid.gridSize.x / 2) >> grid.chunkShift;
            const std::pair<std::string, LodLayout> layouts[] = {
                {"half-space", layoutBy(grid, [&](glm::ivec3 c) { return c.x < half ? 0 : 1; })},
                {"checkerboard", layoutBy(grid, [](glm::ivec3 c) { return (c.x + c.y + c.z) & 1; })},
                {"ring", LodLayout::aroundPoint(grid, glm::vec3(grid.gridOrigin) + glm::vec3(grid.gridSize) * 0.3f, 2)},
            };
            for (const auto& [name, layout] : layouts) {
                const std::string what = f.name + ", " + name + ", chunk " + std::to_string(chunkSize);
                if (name == "ring" && chunkSize == 8) { EXPECT_EQ(levelsPresent(layout), 3) << what; }
                LodStats stats;
                const Mesh mesh = meshLod(pyramid, layout, MeshOptions{}, &stats);
                EXPECT_GT(stats.transitionCells, 0u) << what;
                ASSERT_GT(mesh.triangles.size(), 300u) << what;
                expectCrackFree(mesh, what);
            }
        }
    }
}

// A world that is solid up to its border: level 0's walls lie half a voxel outside the last voxels;
// at levels 1 and 2 (alone and mixed with 0) no wall leaves that box (clamped, instead of moving out
// by up to 2^level - 1/2 voxels), and the mesh stays crack free.
TEST(mesh_Lod, borderWallsStayOnTheWorldsBox) {
    const glm::ivec3 origin(-5, 3, 17), size(40, 24, 33);
    const ChunkedGrid grid = test::makeGrid(origin, size, 8, [](glm::vec3) { return 1.0f; });
    const LodPyramid pyramid(grid, 2);
    const glm::vec3 low = glm::vec3(origin) - 0.5f, high = glm::vec3(origin + size) - 0.5f;
    for (int level : {0, 1, 2}) {
        const std::pair<std::string, LodLayout> layouts[] = {
            {"uniform", LodLayout::uniform(grid.layout(), level)},
            {"ring", LodLayout::aroundPoint(grid.layout(), glm::vec3(origin), level)},
        };
        for (const auto& [name, layout] : layouts) {
            const std::string what = name + " level " + std::to_string(level);
            const Mesh mesh = meshLod(pyramid, layout, MeshOptions{});
            ASSERT_GT(mesh.triangles.size(), 0u) << what;
            glm::vec3 lo(INFINITY), hi(-INFINITY);
            for (const glm::vec3& p : mesh.positions) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
            // Never outside the box; inside it by less than a level-`level` cell (where the coarse
            // lattice's last point inside falls short of the border); exactly on it at level 0.
            const float cell = float(1 << level);
            EXPECT_TRUE(glm::all(glm::greaterThanEqual(lo, low)) && glm::all(glm::lessThan(lo, low + cell))) << what;
            EXPECT_TRUE(glm::all(glm::lessThanEqual(hi, high)) && glm::all(glm::greaterThan(hi, high - cell))) << what;
            if (level == 0) EXPECT_TRUE(lo == low && hi == high) << what;
            expectCrackFree(mesh, what);
        }
    }
}

// L3 on random balanced layouts of levels 0-2 over noise (every neighbourhood of levels).
TEST(mesh_Lod, randomBalancedLayoutsAreCrackFree) {
    const ChunkedGrid grid = stripedNoiseGrid({-3, 5, 2}, {40, 36, 44}, 8, 11);
    const LodPyramid pyramid(grid, 2);
    std::mt19937 random(23);
    for (int trial = 0; trial < 6; ++trial) {
        LodLayout layout = layoutBy(grid.layout(), [&](glm::ivec3) { return int(random() % 3); });
        balanceLod(layout);
        expectCrackFree(meshLod(pyramid, layout, MeshOptions{}), "random layout " + std::to_string(trial));
    }
}

// L4: one transition face per face adjacency whose levels differ, and transition cells exactly
// where a coarse chunk's cell shares an edge or a face with a finer chunk, counted here from boxes.
TEST(mesh_Lod, transitionsAreWhereLevelsDiffer) {
    const ChunkedGrid grid = makeGrid({-5, 3, -9}, {60, 40, 52}, 16, ramp(sphereSdf({20, 22, 15}, 17.0f), 8.0f));
    const LodPyramid pyramid(grid, 2);
    for (const LodLayout& layout : {LodLayout::uniform(grid.layout(), 1), LodLayout::aroundPoint(grid.layout(), {0, 10, 0}, 2),
                                    layoutBy(grid.layout(), [](glm::ivec3 c) { return (c.x + c.y + c.z) & 1; })}) {
        size_t faces = 0, cells = 0;
        const LodLayout all = LodLayout::uniform(grid.layout(), 0);
        const int chunk = layout.chunkSize;
        auto contains = [&](glm::ivec3 c) { return glm::all(glm::greaterThanEqual(c - layout.firstChunk, glm::ivec3(0))) &&
                                                   glm::all(glm::lessThan(c - layout.firstChunk, layout.chunkCount)); };
        for (int i = 0; i < int(layout.levels.size()); ++i) {
            const glm::ivec3 c = layout.firstChunk + glm::ivec3(i % layout.chunkCount.x, (i / layout.chunkCount.x) % layout.chunkCount.y,
                                                               i / (layout.chunkCount.x * layout.chunkCount.y));
            const int level = layout.levelAt(c), step = 1 << level;
            for (int a = 0; a < 3; ++a)
                for (int s : {-1, 1}) {
                    glm::ivec3 n = c;
                    n[a] += s;
                    faces += contains(n) && layout.levelAt(n) < level;
                }
            // Cells of this chunk within the grid's cell range whose closed box meets a finer
            // touching chunk's closed box in a segment or more.
            const glm::ivec3 lowest = glm::ivec3(glm::floor(glm::vec3(grid.layout().gridOrigin - 1) / float(step))) * step;
            const glm::ivec3 highest = grid.layout().gridOrigin + grid.layout().gridSize - 1;
            for (int z = c.z * chunk; z < (c.z + 1) * chunk; z += step)
                for (int y = c.y * chunk; y < (c.y + 1) * chunk; y += step)
                    for (int x = c.x * chunk; x < (c.x + 1) * chunk; x += step) {
                        const glm::ivec3 cell(x, y, z);
                        if (glm::any(glm::lessThan(cell, lowest)) || glm::any(glm::greaterThan(cell, highest))) continue;
                        bool touches = false;
                        for (int dz = -1; dz <= 1 && !touches; ++dz)
                            for (int dy = -1; dy <= 1 && !touches; ++dy)
                                for (int dx = -1; dx <= 1 && !touches; ++dx) {
                                    const glm::ivec3 n = c + glm::ivec3(dx, dy, dz);
                                    if (!contains(n) || layout.levelAt(n) >= level) continue;
                                    const glm::ivec3 lo = glm::max(cell, n * chunk), hi = glm::min(cell + step, (n + 1) * chunk);
                                    const glm::ivec3 extent = hi - lo;
                                    touches = glm::all(glm::greaterThanEqual(extent, glm::ivec3(0))) &&
                                              (extent.x > 0) + (extent.y > 0) + (extent.z > 0) >= 1;
                                }
                        cells += touches;
                    }
        }
        LodStats stats;
        meshLod(pyramid, layout, MeshOptions{}, &stats);
        EXPECT_EQ(stats.transitionFaces, faces);
        EXPECT_EQ(stats.transitionCells, cells);
        EXPECT_EQ(stats.chunks, all.levels.size());
        if (layout.maxLevel() == 1 && levelsPresent(layout) == 1) { EXPECT_EQ(stats.transitionFaces + stats.transitionCells, 0u); }
    }
}

double worstSphereError(const Mesh& mesh, glm::vec3 c, float r) {
    double worst = 0.0;
    for (const glm::vec3& p : mesh.positions) worst = std::max(worst, std::abs(double(glm::length(glm::dvec3(p) - glm::dvec3(c))) - r));
    return worst;
}

// L5 (R8): the sphere c = (64.4, 64.2, 64.7), r = 40.3 on a 128^3 grid with ramp width 8 meshes at
// LOD 0/1/2 within 0.005/0.015/0.06 of the analytic surface; with width 1, LOD 1 misses by > 0.15.
TEST(mesh_Lod, geometricErrorPerLevelFollowsTheRampWidth) {
    const glm::vec3 c(64.4f, 64.2f, 64.7f);
    const float r = 40.3f;
    const double bound[] = {0.005, 0.015, 0.06};
    const ChunkedGrid wide = makeGrid({0, 0, 0}, {128, 128, 128}, 32, ramp(sphereSdf(c, r), 8.0f));
    const LodPyramid pyramid(wide, 2);
    for (int k = 0; k <= 2; ++k) {
        const Mesh mesh = meshLod(pyramid, LodLayout::uniform(wide.layout(), k), MeshOptions{});
        const double error = worstSphereError(mesh, c, r);
        std::cout << "LOD " << k << " (w = 8): " << mesh.triangles.size() / 3 << " triangles, worst error " << error << "\n";
        EXPECT_LE(error, bound[k]) << k;
    }
    // The spec's half-space split (x < 64 at LOD 0, x >= 64 at LOD 1): crack-free, and away from
    // the transition its LOD 0 part is the regular mesh's, vertex for vertex, bit for bit.
    const Mesh split = meshLod(pyramid, layoutBy(wide.layout(), [](glm::ivec3 chunk) { return chunk.x < 2 ? 0 : 1; }), MeshOptions{});
    expectCrackFree(split, "sphere, half-space split");
    const Mesh regular = meshMarchingCubes(wide, MeshOptions{});
    auto lodZeroPart = [](const Mesh& mesh) {
        std::set<std::array<uint32_t, 6>> part;
        for (size_t v = 0; v < mesh.positions.size(); ++v) {
            if (mesh.positions[v].x >= 62.0f) continue;
            std::array<uint32_t, 6> bits;
            std::memcpy(bits.data(), &mesh.positions[v], 12);
            std::memcpy(bits.data() + 3, &mesh.normals[v], 12);
            part.insert(bits);
        }
        return part;
    };
    EXPECT_GT(lodZeroPart(regular).size(), 1000u);
    EXPECT_TRUE(lodZeroPart(split) == lodZeroPart(regular));
    // The mixed ring: its regular cells' vertices keep their level's bound, the transition cells'
    // vertices lie on the finer level's edges, so the same bounds hold for the whole mesh.
    const Mesh ring = meshLod(pyramid, LodLayout::aroundPoint(wide.layout(), c + glm::vec3(r, 0, 0), 2), MeshOptions{});
    EXPECT_LE(worstSphereError(ring, c, r), bound[2]);
    const ChunkedGrid narrow = makeGrid({0, 0, 0}, {128, 128, 128}, 32, ramp(sphereSdf(c, r), 1.0f));
    const double error = worstSphereError(meshLod(LodPyramid(narrow, 1), LodLayout::uniform(narrow.layout(), 1), MeshOptions{}), c, r);
    std::cout << "LOD 1 (w = 1): worst error " << error << "\n";
    EXPECT_GT(error, 0.15);
}

// L6: a carve across the LOD0/LOD1 border, the pyramid refreshed and the mesher updated over the
// edit's box only: the re-meshed chunks are at both levels and on both sides of the border, far
// fewer than all, and the mesh equals one made afresh (so no chunk outside the set changed), and
// stays crack-free.
TEST(mesh_Lod, editAcrossALevelBorderRemeshesWhatItReaches) {
    ChunkedGrid grid = makeGrid({0, 0, 0}, {96, 48, 96}, 16, ramp([](glm::vec3 p) { return p.y - 24.3f; }, 8.0f));
    LodPyramid pyramid(grid, 1);
    const LodLayout layout = layoutBy(grid.layout(), [](glm::ivec3 c) { return c.x < 2 ? 0 : 1; });
    LodMesher mesher(pyramid, layout, MeshOptions{});
    const Mesh before = mesher.mesh();
    const glm::vec3 centre(31.6f, 25.2f, 30.1f);
    const float radius = 7.3f;
    const glm::ivec3 first(glm::floor(centre - radius - 4.0f)), last(glm::ceil(centre + radius + 4.0f));
    for (int z = first.z; z <= last.z; ++z)
        for (int y = first.y; y <= last.y; ++y)
            for (int x = first.x; x <= last.x; ++x) {
                const float brush = std::clamp(0.5f - (glm::length(glm::vec3(x, y, z) - centre) - radius) / 8.0f, 0.0f, 1.0f);
                grid.at({x, y, z}) = std::min(grid.at({x, y, z}), 1.0f - brush);
            }
    pyramid.refresh(first, last);
    const std::vector<glm::ivec3> remeshed = mesher.update(first, last);
    std::set<int> levels, sides;
    for (const glm::ivec3& c : remeshed) {
        levels.insert(layout.levelAt(c));
        sides.insert(c.x < 2);
    }
    EXPECT_EQ(levels.size(), 2u);
    EXPECT_EQ(sides.size(), 2u);
    EXPECT_LT(remeshed.size(), layout.levels.size() / 4);
    const Mesh edited = mesher.mesh();
    EXPECT_FALSE(identical(edited, before));
    EXPECT_TRUE(identical(edited, meshLod(LodPyramid(grid, 1), layout, MeshOptions{})));
    expectCrackFree(edited, "carved across the border");
}

// L7 (M6, M10): a layout of only level 0 is the regular mesher's mesh byte for byte, at every
// chunk size and origin; a uniform coarse level is the same for every chunk size; a mixed layout
// is the same twice, with and without uniform-chunk skipping.
TEST(mesh_Lod, levelZeroIsTheRegularMeshAndChunkSizeDoesNotShow) {
    for (glm::ivec3 origin : {glm::ivec3(0), glm::ivec3(-37, -5, -70), glm::ivec3(1000, 17, -999)}) {
        std::vector<Mesh> coarse;
        for (int32_t chunkSize : {8, 16, 32}) {
            const ChunkedGrid grid = stripedNoiseGrid(origin, {41, 27, 35}, chunkSize, 9);
            const LodPyramid pyramid(grid, 1);
            EXPECT_TRUE(identical(meshLod(pyramid, LodLayout::uniform(grid.layout(), 0), MeshOptions{}), meshMarchingCubes(grid, MeshOptions{})))
                << "chunk " << chunkSize;
            coarse.push_back(meshLod(pyramid, LodLayout::uniform(grid.layout(), 1), MeshOptions{}));
            expectCrackFree(coarse.back(), "uniform level 1");
            if (coarse.size() > 1) { EXPECT_TRUE(identical(coarse.back(), coarse.front())) << "level 1, chunk " << chunkSize; }

            const LodLayout ring = LodLayout::aroundPoint(grid.layout(), glm::vec3(origin) + 4.0f, 1);
            const Mesh mixed = meshLod(pyramid, ring, MeshOptions{});
            EXPECT_TRUE(identical(mixed, meshLod(pyramid, ring, MeshOptions{})));
            EXPECT_TRUE(identical(mixed, meshLod(pyramid, ring, MeshOptions{.skipUniformChunks = false})));
        }
    }
}

} // namespace lod_test
} // namespace voxc
