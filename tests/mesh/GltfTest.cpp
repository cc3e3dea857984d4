// .glb export (spec G2-G8): container bytes, round trip, bounds, normals, colours, primitives
// and winding, read back with the tests' own reader (GlbReader.h).
#include "GlbReader.h"
#include "TestGrids.h"
#include "voxc/mesh/Export.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/mesh/MeshQuality.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <map>
#include <meshoptimizer.h>
#include <set>
#include <unistd.h>

namespace voxc {
namespace gltf_test {

using test::GlbFile;
using test::parseGlb;

const std::vector<Material> kMaterials = {
    {"rock", {}, 1, {0.5f, 0.25f, 1.0f}},
    {"sand", {}, 2, {0.86f, 0.78f, 0.55f}},
    {"grass", {}, 7, {0.2f, 0.6f, 0.1f}},
};

// A ball and a slab with three declared materials and one undeclared id (9).
Mesh materialMesh() {
    ChunkedGrid grid = test::makeGrid({-4, 2, 5}, {30, 22, 26}, 16, [](glm::vec3 p) {
        return std::max(test::coneBall({10.4f, 12.2f, 17.7f}, 9.0f)(p), test::box({-2, 4, 8}, {24, 8, 28})(p));
    });
    test::paintMaterials(grid, [](glm::ivec3 p) { return uint8_t(p.x < 4 ? 1 : p.x < 10 ? 2 : p.x < 16 ? 7 : 9); });
    return meshMarchingCubes(grid, MeshOptions{});
}

using Triangle = std::array<uint32_t, 3>;

// A triangle rotated to start at its smallest index: the same triangle, the same winding.
Triangle canonical(uint32_t a, uint32_t b, uint32_t c) {
    Triangle t = {a, b, c};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
}

// A .glb read back in terms of the mesh it was written from. The writer reorders vertices and
// triangles for rendering, so vertices are matched by their position and normal bits (every
// one must match exactly one mesh vertex) and each primitive's triangles compared as a set.
struct ReadBack {
    std::vector<uint32_t> meshVertex;       // file vertex -> mesh vertex
    std::map<uint8_t, std::vector<Triangle>> triangles; // by voxc material id, in mesh vertices, sorted
};

ReadBack readBack(const GlbFile& f, const Mesh& mesh) {
    ReadBack r;
    const auto& primitives = f.json["meshes"][0]["primitives"];
    const auto& attributes = primitives[0]["attributes"];
    const std::vector<float> p = test::accessorValues<float>(f, attributes["POSITION"]), n = test::accessorValues<float>(f, attributes["NORMAL"]);
    std::map<std::array<uint32_t, 6>, uint32_t> byBits;
    for (uint32_t v = 0; v < mesh.positions.size(); ++v) {
        std::array<uint32_t, 6> bits;
        std::memcpy(bits.data(), &mesh.positions[v], 12);
        std::memcpy(bits.data() + 3, &mesh.normals[v], 12);
        EXPECT_TRUE(byBits.emplace(bits, v).second) << "two mesh vertices with the same bits";
    }
    std::set<uint32_t> matched;
    for (size_t v = 0; v * 3 < p.size(); ++v) {
        std::array<uint32_t, 6> bits;
        std::memcpy(bits.data(), &p[3 * v], 12);
        std::memcpy(bits.data() + 3, &n[3 * v], 12);
        const auto it = byBits.find(bits);
        EXPECT_NE(it, byBits.end()) << "file vertex " << v << " is no mesh vertex";
        if (it == byBits.end()) continue;
        r.meshVertex.push_back(it->second);
        matched.insert(it->second);
    }
    EXPECT_EQ(matched.size(), mesh.positions.size());
    EXPECT_EQ(r.meshVertex.size(), mesh.positions.size());
    for (const auto& primitive : primitives) {
        EXPECT_EQ(primitive.value("mode", 4), 4);
        EXPECT_EQ(primitive["attributes"], attributes);
        const std::vector<uint32_t> indices = test::indexValues(f, primitive["indices"]);
        EXPECT_FALSE(indices.empty());
        EXPECT_EQ(indices.size() % 3, 0u);
        for (uint32_t i : indices) EXPECT_LT(i, r.meshVertex.size());
        if (indices.empty() || indices.size() % 3 != 0 || *std::max_element(indices.begin(), indices.end()) >= r.meshVertex.size()) continue;
        const uint8_t id = f.json["materials"][primitive["material"].get<size_t>()]["extras"]["voxc_material_id"];
        std::vector<Triangle>& list = r.triangles[id];
        EXPECT_TRUE(list.empty()) << "two primitives of material " << int(id);
        for (size_t t = 0; t < indices.size(); t += 3)
            list.push_back(canonical(r.meshVertex[indices[t]], r.meshVertex[indices[t + 1]], r.meshVertex[indices[t + 2]]));
        std::sort(list.begin(), list.end());
    }
    return r;
}

// The mesh's triangles by material id, canonical and sorted, as readBack gives them.
std::map<uint8_t, std::vector<Triangle>> trianglesByMaterial(const Mesh& mesh) {
    std::map<uint8_t, std::vector<Triangle>> groups;
    for (size_t t = 0; t < mesh.triangles.size() / 3; ++t)
        groups[mesh.triangleMaterials[t]].push_back(canonical(mesh.triangles[3 * t], mesh.triangles[3 * t + 1], mesh.triangles[3 * t + 2]));
    for (auto& [id, list] : groups) std::sort(list.begin(), list.end());
    return groups;
}

// G2
TEST(mesh_Glb, containerFollowsTheGlbLayout) {
    const Mesh mesh = materialMesh();
    const std::string bytes = encodeGlb(mesh, kMaterials);
    const GlbFile f = parseGlb(bytes);
    EXPECT_EQ(f.json["asset"]["version"], "2.0");
    ASSERT_EQ(f.json["buffers"].size(), 1u);
    EXPECT_FALSE(f.json["buffers"][0].contains("uri"));
    const size_t byteLength = f.json["buffers"][0]["byteLength"];
    EXPECT_LE(byteLength, f.bin.size());
    EXPECT_LE(f.bin.size(), byteLength + 3);
    for (size_t i = byteLength; i < f.bin.size(); ++i) EXPECT_EQ(f.bin[i], '\0');
    for (const auto& view : f.json["bufferViews"]) {
        EXPECT_EQ(view["byteOffset"].get<size_t>() % 4, 0u);
        EXPECT_FALSE(view.contains("byteStride"));
    }
}

// G3, G4, G5, G7: everything comes back exactly, up to the order the writer chose.
TEST(mesh_Glb, roundTripGivesTheMeshBack) {
    const Mesh mesh = materialMesh();
    const GlbFile f = parseGlb(encodeGlb(mesh, kMaterials));
    const ReadBack r = readBack(f, mesh);
    EXPECT_EQ(r.triangles, trianglesByMaterial(mesh));

    // Bounds: the float extrema exactly, read as double.
    const size_t position = f.json["meshes"][0]["primitives"][0]["attributes"]["POSITION"];
    for (int a = 0; a < 3; ++a) {
        float lo = mesh.positions[0][a], hi = lo;
        for (const glm::vec3& p : mesh.positions) {
            lo = std::min(lo, p[a]);
            hi = std::max(hi, p[a]);
        }
        EXPECT_EQ(f.json["accessors"][position]["min"][a].get<double>(), double(lo));
        EXPECT_EQ(f.json["accessors"][position]["max"][a].get<double>(), double(hi));
    }
    for (const glm::vec3& n : mesh.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);

    std::set<std::string> names;
    for (const auto& material : f.json["materials"]) names.insert(material["name"].get<std::string>());
    EXPECT_EQ(names, (std::set<std::string>{"rock", "sand", "grass", "material9"}));
    EXPECT_EQ(f.json["materials"].size(), f.json["meshes"][0]["primitives"].size());
}

// The writer reorders for the GPU's vertex cache: fewer vertex shader runs per triangle (ACMR,
// a 16-entry FIFO cache simulated by meshoptimizer's analyzer) than the mesher's cell order.
TEST(mesh_Glb, trianglesAreOrderedForTheVertexCache) {
    const Mesh mesh = meshMarchingCubes(test::makeGrid({0, 0, 0}, {40, 40, 40}, 16, test::coneBall({19.5f, 20.2f, 18.7f}, 17.0f)), MeshOptions{});
    const GlbFile f = parseGlb(encodeGlb(mesh));
    const std::vector<uint32_t> written = test::indexValues(f, f.json["meshes"][0]["primitives"][0]["indices"]);
    const double before = meshopt_analyzeVertexCache(mesh.triangles.data(), mesh.triangles.size(), mesh.positions.size(), 16, 0, 0).acmr;
    const double after = meshopt_analyzeVertexCache(written.data(), written.size(), mesh.positions.size(), 16, 0, 0).acmr;
    EXPECT_LT(after, 0.8 * before) << "ACMR " << before << " -> " << after;
}

// A mesh of many reordering blocks (the writer reorders blocks of triangles apart, on threads):
// its cache efficiency stays within 2% of reordering the whole list at once.
TEST(mesh_Glb, blockwiseCacheOrderMatchesTheWholeListsOrder) {
    const Mesh mesh = meshMarchingCubes(test::makeGrid({0, 0, 0}, {128, 128, 128}, 32, test::coneBall({63.5f, 64.2f, 62.7f}, 116.0f)), MeshOptions{});
    ASSERT_GT(mesh.triangles.size() / 3, 100000u); // several blocks of 16,384 triangles
    const GlbFile f = parseGlb(encodeGlb(mesh));
    ASSERT_EQ(f.json["meshes"][0]["primitives"].size(), 1u);
    const std::vector<uint32_t> written = test::indexValues(f, f.json["meshes"][0]["primitives"][0]["indices"]);
    std::vector<uint32_t> whole(mesh.triangles.size());
    meshopt_optimizeVertexCacheFifo(whole.data(), mesh.triangles.data(), mesh.triangles.size(), mesh.positions.size(), 16);
    const double blockwise = meshopt_analyzeVertexCache(written.data(), written.size(), mesh.positions.size(), 16, 0, 0).acmr;
    const double best = meshopt_analyzeVertexCache(whole.data(), whole.size(), mesh.positions.size(), 16, 0, 0).acmr;
    EXPECT_LT(blockwise, 1.02 * best) << "ACMR " << best << " (whole list) against " << blockwise << " (blocks)";
}

// G6: each primitive's material carries its colour as the base colour, linear as declared (grey
// 0.6 for an undeclared id), so materials differ in more than their names (assimp's post-processing
// merges materials that differ only there); the vertices carry no colour stream.
TEST(mesh_Glb, materialsCarryTheirColourAsBaseColour) {
    const Mesh mesh = materialMesh();
    const GlbFile f = parseGlb(encodeGlb(mesh, kMaterials));
    const std::map<int, glm::vec3> expected = {{1, kMaterials[0].color}, {2, kMaterials[1].color}, {7, kMaterials[2].color}, {9, glm::vec3(0.6f)}};
    std::set<std::vector<double>> distinct;
    for (const auto& primitive : f.json["meshes"][0]["primitives"]) {
        EXPECT_FALSE(primitive["attributes"].contains("COLOR_0"));
        const auto& material = f.json["materials"][size_t(primitive["material"])];
        const int id = material["extras"]["voxc_material_id"];
        ASSERT_TRUE(expected.count(id)) << id;
        const std::vector<double> base = material["pbrMetallicRoughness"]["baseColorFactor"];
        ASSERT_EQ(base.size(), 4u);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(float(base[size_t(c)]), expected.at(id)[c]) << id;
        EXPECT_EQ(base[3], 1.0);
        distinct.insert(base);
    }
    EXPECT_EQ(distinct.size(), 4u);
}

// G8: front faces counter-clockwise seen from outside, and the normals agree with them (on a
// smooth ball: at the slab's hard edges gradient normals and faces part ways by design).
TEST(mesh_Glb, windingFacesOutwardAndAgreesWithNormals) {
    const Mesh mesh = meshMarchingCubes(test::makeGrid({3, -7, 1}, {24, 24, 24}, 8, test::coneBall({15.2f, 4.6f, 13.3f}, 10.0f)), MeshOptions{});
    const GlbFile f = parseGlb(encodeGlb(mesh, kMaterials));
    Mesh read;
    const auto& primitives = f.json["meshes"][0]["primitives"];
    const std::vector<float> p = test::accessorValues<float>(f, primitives[0]["attributes"]["POSITION"]);
    const std::vector<float> n = test::accessorValues<float>(f, primitives[0]["attributes"]["NORMAL"]);
    for (size_t i = 0; i < p.size(); i += 3) {
        read.positions.push_back({p[i], p[i + 1], p[i + 2]});
        read.normals.push_back({n[i], n[i + 1], n[i + 2]});
    }
    for (const auto& primitive : primitives)
        for (uint32_t i : test::indexValues(f, primitive["indices"])) read.triangles.push_back(i);
    const MeshQuality q = measureMeshQuality(read);
    EXPECT_TRUE(q.manifold()) << describeMeshQuality(q);
    EXPECT_GT(q.signedVolume, 0.0);
    size_t agree = 0;
    for (size_t t = 0; t < read.triangles.size(); t += 3) {
        const glm::vec3 a = read.positions[read.triangles[t]], b = read.positions[read.triangles[t + 1]], c = read.positions[read.triangles[t + 2]];
        const glm::vec3 face = glm::cross(b - a, c - a);
        agree += glm::dot(face, read.normals[read.triangles[t]] + read.normals[read.triangles[t + 1]] + read.normals[read.triangles[t + 2]]) > 0.0f;
    }
    EXPECT_GE(agree * 100, (read.triangles.size() / 3) * 99);
}

TEST(mesh_Glb, manyVerticesUse32BitIndices) {
    ChunkedGrid grid(ChunkLayout::make({0, 0, 0}, {40, 40, 40}, 32));
    for (int z = 0; z < 40; ++z)
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 40; ++x) grid.at({x, y, z}) = float((x * 7 + y * 13 + z * 5) % 3) * 0.45f;
    const Mesh mesh = meshMarchingCubes(grid, MeshOptions{});
    ASSERT_GT(mesh.positions.size(), 65535u);
    const GlbFile f = parseGlb(encodeGlb(mesh));
    const size_t indices = f.json["meshes"][0]["primitives"][0]["indices"];
    EXPECT_EQ(f.json["accessors"][indices]["componentType"], 5125);
    EXPECT_EQ(readBack(f, mesh).triangles, trianglesByMaterial(mesh));
    EXPECT_EQ(f.json["materials"][0]["name"], "none");
}

TEST(mesh_Glb, fewVerticesUse16BitIndices) {
    const Mesh mesh = materialMesh();
    ASSERT_LT(mesh.positions.size(), 65535u);
    const GlbFile f = parseGlb(encodeGlb(mesh, kMaterials));
    for (const auto& p : f.json["meshes"][0]["primitives"]) EXPECT_EQ(f.json["accessors"][p["indices"].get<size_t>()]["componentType"], 5123);
}

TEST(mesh_Glb, emptyMeshIsAnEmptySceneWithoutBinChunk) {
    const std::string bytes = encodeGlb(Mesh{});
    const GlbFile f = parseGlb(bytes);
    EXPECT_TRUE(f.bin.empty());
    EXPECT_EQ(bytes.size(), 20u + f.jsonChunkLength);
    EXPECT_EQ(f.json["scenes"].size(), 1u);
    EXPECT_FALSE(f.json["scenes"][0].contains("nodes"));
    EXPECT_FALSE(f.json.contains("meshes"));
    EXPECT_FALSE(f.json.contains("buffers"));
}

TEST(mesh_Glb, writeMeshPicksGlbByExtension) {
    const auto dir = std::filesystem::temp_directory_path() / ("voxc_glb_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "ball.GLB").string();
    const Mesh mesh = materialMesh();
    writeMesh(path, mesh, kMaterials);
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(bytes, encodeGlb(mesh, kMaterials));
    std::filesystem::remove_all(dir);
}

} // namespace gltf_test
} // namespace voxc
