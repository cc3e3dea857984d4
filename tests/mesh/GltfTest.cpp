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
#include <set>
#include <unistd.h>

namespace voxc {
namespace {

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

// The mesh's triangles grouped by material, ascending id, each group in mesh order.
std::vector<uint32_t> trianglesInPrimitiveOrder(const Mesh& mesh, std::vector<uint8_t>& materials) {
    std::vector<uint32_t> out;
    materials.clear();
    for (unsigned id = 0; id < 256; ++id)
        for (size_t t = 0; t < mesh.triangleMaterials.size(); ++t)
            if (mesh.triangleMaterials[t] == id) {
                out.insert(out.end(), mesh.triangles.begin() + std::ptrdiff_t(3 * t), mesh.triangles.begin() + std::ptrdiff_t(3 * t + 3));
                materials.push_back(uint8_t(id));
            }
    return out;
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

// G3, G4, G5, G7: everything comes back exactly.
TEST(mesh_Glb, roundTripGivesTheMeshBack) {
    const Mesh mesh = materialMesh();
    const GlbFile f = parseGlb(encodeGlb(mesh, kMaterials));
    const auto& primitives = f.json["meshes"][0]["primitives"];
    const size_t position = primitives[0]["attributes"]["POSITION"], normal = primitives[0]["attributes"]["NORMAL"];
    const std::vector<float> positions = test::accessorValues<float>(f, position), normals = test::accessorValues<float>(f, normal);
    ASSERT_EQ(positions.size(), mesh.positions.size() * 3);
    EXPECT_EQ(std::memcmp(positions.data(), mesh.positions.data(), positions.size() * 4), 0);
    EXPECT_EQ(std::memcmp(normals.data(), mesh.normals.data(), normals.size() * 4), 0);

    // Bounds: the float extrema exactly, read as double.
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

    std::vector<uint8_t> expectedMaterials;
    const std::vector<uint32_t> expected = trianglesInPrimitiveOrder(mesh, expectedMaterials);
    std::vector<uint32_t> triangles;
    std::vector<uint8_t> triangleMaterials;
    std::set<std::string> names;
    for (const auto& p : primitives) {
        EXPECT_EQ(p.value("mode", 4), 4);
        EXPECT_EQ(p["attributes"]["POSITION"], position);
        const std::vector<uint32_t> indices = test::indexValues(f, p["indices"]);
        ASSERT_FALSE(indices.empty());
        ASSERT_EQ(indices.size() % 3, 0u);
        for (uint32_t i : indices) ASSERT_LT(i, mesh.positions.size());
        const auto& material = f.json["materials"][p["material"].get<size_t>()];
        names.insert(material["name"].get<std::string>());
        triangles.insert(triangles.end(), indices.begin(), indices.end());
        triangleMaterials.insert(triangleMaterials.end(), indices.size() / 3, material["extras"]["voxc_material_id"].get<uint8_t>());
    }
    EXPECT_EQ(triangles, expected);
    EXPECT_EQ(triangleMaterials, expectedMaterials);
    EXPECT_EQ(names, (std::set<std::string>{"rock", "sand", "grass", "material9"}));
    EXPECT_EQ(f.json["materials"].size(), primitives.size());
}

// G6: COLOR_0 is the vertex's material colour, linear as declared, as normalised RGBA bytes.
TEST(mesh_Glb, vertexColoursAreNormalisedMaterialColourBytes) {
    const Mesh mesh = materialMesh();
    const GlbFile f = parseGlb(encodeGlb(mesh, kMaterials));
    const size_t color = f.json["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"];
    const auto& accessor = f.json["accessors"][color];
    EXPECT_EQ(accessor["componentType"], 5121);
    EXPECT_EQ(accessor["type"], "VEC4");
    EXPECT_EQ(accessor["normalized"], true);
    const std::vector<uint8_t> bytes = test::accessorValues<uint8_t>(f, color);
    ASSERT_EQ(bytes.size(), mesh.positions.size() * 4);
    const std::map<uint8_t, std::array<uint8_t, 4>> expected = {
        {1, {128, 64, 255, 255}}, {2, {219, 199, 140, 255}}, {7, {51, 153, 26, 255}}, {9, {153, 153, 153, 255}}};
    std::set<uint8_t> seen;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const std::array<uint8_t, 4> rgba = {bytes[4 * v], bytes[4 * v + 1], bytes[4 * v + 2], bytes[4 * v + 3]};
        EXPECT_EQ(rgba, expected.at(mesh.vertexMaterials[v])) << v;
        seen.insert(mesh.vertexMaterials[v]);
    }
    EXPECT_EQ(seen.size(), 4u);
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
    EXPECT_EQ(test::indexValues(f, indices), mesh.triangles);
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

} // namespace
} // namespace voxc
