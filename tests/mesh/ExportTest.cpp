#include "TestGrids.h"
#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/mesh/Export.h"
#include "voxc/mesh/SurfaceNets.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace voxc {
namespace {

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

} // namespace
} // namespace voxc
