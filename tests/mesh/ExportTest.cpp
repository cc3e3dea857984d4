#include "TestGrids.h"
#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/mesh/Export.h"
#include "voxc/mesh/SurfaceNets.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <set>
#include <sstream>

namespace voxc {
namespace export_test {

Mesh ballMesh() {
    return meshSurfaceNets(test::makeGrid({-4, 0, 7}, {12, 11, 13}, 8, test::coneBall({1.5f, 5.2f, 13.1f}, 9.0f)), 0.5f);
}

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(mesh_Export, plyReadsBackAsTheSameMesh) {
    const Mesh mesh = ballMesh();
    ASSERT_FALSE(mesh.triangles.empty());
    const std::string path = testing::TempDir() + "mesh_ball.ply";
    writePly(path, mesh);
    const Mesh back = readPly(path);
    EXPECT_EQ(back.positions, mesh.positions);
    EXPECT_EQ(back.normals, mesh.normals);
    EXPECT_EQ(back.triangles, mesh.triangles);
    EXPECT_EQ(std::filesystem::file_size(path),
              readText(path).find("end_header\n") + 11 + mesh.positions.size() * 24 + mesh.triangles.size() / 3 * 13);
}

TEST(mesh_Export, objHasOneLinePerVertexNormalAndFace) {
    const Mesh mesh = ballMesh();
    const std::string path = testing::TempDir() + "mesh_ball.obj";
    writeObj(path, mesh);
    std::istringstream lines(readText(path));
    size_t v = 0, vn = 0, f = 0;
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string tag;
        words >> tag;
        if (tag == "v" || tag == "vn") {
            float x, y, z;
            ASSERT_TRUE(words >> x >> y >> z) << line;
            const glm::vec3 expected = tag == "v" ? mesh.positions[v] : mesh.normals[vn];
            EXPECT_EQ(glm::vec3(x, y, z), expected) << line; // shortest round-trip text
            ++(tag == "v" ? v : vn);
        } else if (tag == "f") {
            for (size_t k = 0; k < 3; ++k) {
                std::string corner;
                ASSERT_TRUE(words >> corner) << line;
                const size_t slashes = corner.find("//");
                ASSERT_NE(slashes, std::string::npos) << line;
                const unsigned long index = std::stoul(corner.substr(0, slashes));
                EXPECT_EQ(corner.substr(slashes + 2), corner.substr(0, slashes));
                EXPECT_EQ(index, mesh.triangles[f * 3 + k] + 1ul);
            }
            ++f;
        } else {
            EXPECT_EQ(tag, "#") << line;
        }
    }
    EXPECT_EQ(v, mesh.positions.size());
    EXPECT_EQ(vn, mesh.normals.size());
    EXPECT_EQ(f, mesh.triangles.size() / 3);
}

TEST(mesh_Export, writeMeshChoosesTheFormatByExtension) {
    const Mesh mesh = ballMesh();
    const std::string dir = testing::TempDir();
    writeMesh(dir + "mesh_choice.PLY", mesh);
    EXPECT_EQ(readPly(dir + "mesh_choice.PLY").triangles, mesh.triangles);
    writeMesh(dir + "mesh_choice.obj", mesh);
    EXPECT_EQ(readText(dir + "mesh_choice.obj").rfind("# voxc", 0), 0u);
    EXPECT_THROW(writeMesh(dir + "mesh_choice.stl", mesh), UserError);
    EXPECT_FALSE(std::filesystem::exists(dir + "mesh_choice.stl"));
}

TEST(mesh_Export, malformedPlyIsAUserError) {
    const std::string dir = testing::TempDir();
    writeFileAtomically(dir + "mesh_text.ply", std::string("ply\nformat ascii 1.0\nend_header\n"));
    EXPECT_THROW(readPly(dir + "mesh_text.ply"), UserError);

    const std::string good = dir + "mesh_cut.ply";
    writePly(good, ballMesh());
    const std::string bytes = readText(good);
    writeFileAtomically(good, bytes.substr(0, bytes.size() - 5));
    EXPECT_THROW(readPly(good), UserError);
    EXPECT_THROW(readPly(dir + "mesh_missing.ply"), UserError);
}

// A ball whose lower half is rock (1) and upper half sand (2), plus one vertex of an undeclared id.
Mesh materialBallMesh() {
    ChunkedGrid grid = test::makeGrid({-4, 0, 7}, {12, 11, 13}, 8, test::coneBall({1.5f, 5.2f, 13.1f}, 9.0f));
    test::paintMaterials(grid, [](glm::ivec3 p) { return uint8_t(p.y < 5 ? 1 : p.y < 8 ? 2 : 7); });
    return meshSurfaceNets(grid, 0.5f);
}

// sRGB encoding of a linear channel (IEC 61966-2-1), in double, independent of the exporter's.
double srgb(double linear) { return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055; }

// A .mtl of one `newmtl` + `Kd` per material, in order, with Kd the sRGB encoding of the linear colour.
void expectMaterialLibrary(const std::string& text, const std::vector<std::pair<std::string, glm::vec3>>& expected) {
    std::istringstream lines(text);
    std::string line;
    std::getline(lines, line);
    EXPECT_EQ(line, "# voxc materials");
    for (const auto& [name, linear] : expected) {
        std::getline(lines, line);
        EXPECT_EQ(line, "newmtl " + name);
        std::string keyword;
        double r = -1, g = -1, b = -1;
        lines >> keyword >> r >> g >> b;
        lines.ignore(1);
        EXPECT_EQ(keyword, "Kd") << name;
        EXPECT_NEAR(r, srgb(linear.r), 1e-6) << name;
        EXPECT_NEAR(g, srgb(linear.g), 1e-6) << name;
        EXPECT_NEAR(b, srgb(linear.b), 1e-6) << name;
    }
    EXPECT_FALSE(std::getline(lines, line)) << "more lines than materials: " << line;
}

std::vector<Material> rockAndSand() {
    Material rock{.name = "rock", .loc = {}, .id = 1, .color = {1.0f, 0.5f, 0.0f}};
    Material sand{.name = "sand", .loc = {}, .id = 2, .color = {0.2f, 0.4f, 0.6f}};
    return {rock, sand};
}

TEST(mesh_Export, plyCarriesVertexMaterialsAndColours) {
    const Mesh mesh = materialBallMesh();
    const std::string path = testing::TempDir() + "mesh_materials.ply";
    writePly(path, mesh, rockAndSand());
    const std::string bytes = readText(path);
    const std::string header = bytes.substr(0, bytes.find("end_header\n") + 11);
    EXPECT_NE(header.find("property float nz\nproperty uchar material\nproperty uchar red\nproperty uchar green\n"
                          "property uchar blue\nelement face"),
              std::string::npos);
    EXPECT_NE(header.find("property list uchar int vertex_indices\nproperty uchar material\nend_header"),
              std::string::npos);
    EXPECT_EQ(bytes.size(), header.size() + mesh.positions.size() * 28 + mesh.triangles.size() / 3 * 14);
    std::vector<Material> colours;
    const Mesh back = readPly(path, &colours);
    EXPECT_EQ(back.positions, mesh.positions);
    EXPECT_EQ(back.triangles, mesh.triangles);
    EXPECT_EQ(back.vertexMaterials, mesh.vertexMaterials);
    EXPECT_EQ(back.triangleMaterials, mesh.triangleMaterials);
    // The colours read back (decoded from sRGB bytes): rock and sand as declared, the undeclared
    // id 7 neutral grey (0.6), each within the rounding of a byte.
    ASSERT_EQ(colours.size(), 3u);
    const auto near = [](glm::vec3 a, glm::vec3 b) { return glm::all(glm::lessThan(glm::abs(a - b), glm::vec3(0.004f))); };
    EXPECT_EQ(colours[0].id, 1);
    EXPECT_TRUE(near(colours[0].color, {1.0f, 0.5f, 0.0f}));
    EXPECT_EQ(colours[1].id, 2);
    EXPECT_TRUE(near(colours[1].color, {0.2f, 0.4f, 0.6f}));
    EXPECT_EQ(colours[2].name, "material7");
    EXPECT_TRUE(near(colours[2].color, glm::vec3(0.6f)));
    // The bytes are sRGB, as PLY viewers read them: linear 0.5 -> 188, 0.2 -> 124, 0.4 -> 170, 0.6 -> 203.
    const std::map<uint8_t, std::array<uint8_t, 3>> colors = {{1, {255, 188, 0}}, {2, {124, 170, 203}}, {7, {203, 203, 203}}};
    std::set<uint8_t> seen;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const char* record = bytes.data() + header.size() + v * 28 + 24;
        const uint8_t id = uint8_t(record[0]);
        seen.insert(id);
        ASSERT_TRUE(colors.count(id)) << int(id);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(uint8_t(record[1 + c]), colors.at(id)[size_t(c)]);
    }
    EXPECT_EQ(seen, (std::set<uint8_t>{1, 2, 7}));
}

// A plain mesh and no material list keep the plain format; a material list alone turns it on.
TEST(mesh_Export, materialPropertiesOnlyWhenUsed) {
    const std::string path = testing::TempDir() + "mesh_plain.ply";
    writePly(path, ballMesh());
    EXPECT_EQ(readText(path).find("material"), std::string::npos);
    EXPECT_TRUE(readPly(path).vertexMaterials.empty());
    writePly(path, ballMesh(), rockAndSand());
    EXPECT_NE(readText(path).find("property uchar material"), std::string::npos);
    EXPECT_EQ(readPly(path).vertexMaterials, std::vector<uint8_t>(ballMesh().positions.size(), 0));
    const std::string obj = testing::TempDir() + "mesh_plain.obj";
    writeObj(obj, ballMesh());
    EXPECT_EQ(readText(obj).find("mtllib"), std::string::npos);
}

TEST(mesh_Export, objGroupsFacesByMaterialWithALibraryBesideIt) {
    const Mesh mesh = materialBallMesh();
    const std::string dir = testing::TempDir() + "mesh_obj_materials/";
    std::filesystem::create_directories(dir);
    writeMesh(dir + "ball.OBJ", mesh, rockAndSand());
    ASSERT_TRUE(std::filesystem::exists(dir + "ball.mtl"));
    expectMaterialLibrary(readText(dir + "ball.mtl"), {{"rock", {1.0f, 0.5f, 0.0f}}, {"sand", {0.2f, 0.4f, 0.6f}}, {"material7", glm::vec3(0.6f)}});

    std::istringstream lines(readText(dir + "ball.OBJ"));
    std::string line, group;
    std::vector<std::string> groups;
    std::map<std::string, uint8_t> ids = {{"rock", 1}, {"sand", 2}, {"material7", 7}};
    size_t faces = 0;
    bool libraryNamed = false;
    while (std::getline(lines, line)) {
        if (line == "mtllib ball.mtl") libraryNamed = true;
        if (line.rfind("g ", 0) == 0) {
            group = line.substr(2);
            groups.push_back(group);
            ASSERT_TRUE(std::getline(lines, line));
            EXPECT_EQ(line, "usemtl " + group);
        }
        if (line.rfind("f ", 0) != 0) continue;
        ASSERT_FALSE(group.empty()) << "a face before the first group";
        // Faces keep their order within a group: find this face's triangle index.
        std::istringstream words(line.substr(2));
        std::string corner;
        uint32_t indices[3];
        for (uint32_t& index : indices) {
            words >> corner;
            index = uint32_t(std::stoul(corner.substr(0, corner.find("//")))) - 1;
        }
        size_t t = 0;
        while (t < mesh.triangleMaterials.size() &&
               !(mesh.triangles[t * 3] == indices[0] && mesh.triangles[t * 3 + 1] == indices[1] && mesh.triangles[t * 3 + 2] == indices[2]))
            ++t;
        ASSERT_LT(t, mesh.triangleMaterials.size()) << line;
        EXPECT_EQ(mesh.triangleMaterials[t], ids.at(group)) << line;
        ++faces;
    }
    EXPECT_TRUE(libraryNamed);
    EXPECT_EQ(groups, (std::vector<std::string>{"rock", "sand", "material7"}));
    EXPECT_EQ(faces, mesh.triangles.size() / 3);
}

TEST(mesh_Export, objMaterialGroupOfNoneWhenOnlyTheListIsGiven) {
    const std::string path = testing::TempDir() + "mesh_none.obj";
    writeObj(path, ballMesh(), rockAndSand());
    const std::string text = readText(path);
    EXPECT_NE(text.find("mtllib mesh_none.mtl\n"), std::string::npos);
    EXPECT_NE(text.find("g none\nusemtl none\n"), std::string::npos);
    expectMaterialLibrary(readText(testing::TempDir() + "mesh_none.mtl"), {{"none", glm::vec3(0.6f)}});
}

TEST(mesh_Export, unwritableObjLeavesNoFiles) {
    const std::string dir = testing::TempDir() + "mesh_no_such_dir/";
    EXPECT_THROW(writeObj(dir + "x.obj", materialBallMesh(), rockAndSand()), UserError);
    EXPECT_THROW(writePly(dir + "x.ply", materialBallMesh(), rockAndSand()), UserError);
    EXPECT_FALSE(std::filesystem::exists(dir));
    // The OBJ's name is taken by a directory: its library is not written either.
    const std::string taken = testing::TempDir() + "mesh_taken.obj";
    std::filesystem::create_directories(taken);
    EXPECT_THROW(writeObj(taken, materialBallMesh(), rockAndSand()), UserError);
    EXPECT_FALSE(std::filesystem::exists(testing::TempDir() + "mesh_taken.mtl"));
}

// A failed OBJ export must not touch the .mtl the user already has beside it.
TEST(mesh_Export, failedObjKeepsThePreviousLibrary) {
    const std::string dir = testing::TempDir() + "mesh_keep_library/";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir + "scene.obj");
    std::ofstream(dir + "scene.mtl") << "newmtl the_users_own\n";
    EXPECT_THROW(writeObj(dir + "scene.obj", materialBallMesh(), rockAndSand()), UserError);
    EXPECT_EQ(readText(dir + "scene.mtl"), "newmtl the_users_own\n");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 2);
}

} // namespace export_test
} // namespace voxc
