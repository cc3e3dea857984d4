// Heightmap and mesh blocks on the CPU (docs/language.md, "Heightmaps", "Meshes"): a height image
// of an analytic function, written by the test in every format, round-trips through the
// interpreter within half a voxel per column; meshes of a sphere and a box give signed distances
// whose sign agrees with the solid at every voxel farther than one voxel from its surface; every
// malformed or oversized file is a located error at the block's `file` value.
#include "InputFiles.h"

#include "voxc/check/Check.h"
#include "voxc/check/LoadPackage.h"
#include "voxc/codegen/PackageWriter.h"
#include "voxc/stages/Pipeline.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace voxc {
namespace inputs_test {

namespace fs = std::filesystem;

fs::path scratch() {
    const fs::path dir = fs::temp_directory_path() / fmt::format("voxc_inputs_test_{}", ::getpid());
    fs::create_directories(dir);
    return dir;
}

CheckResult checkAt(const fs::path& vox, const std::string& text, const Limits& limits = {}) {
    return checkSource(SourceFile(vox.string(), text), limits);
}

// The test's ground: f(x, z) world voxels high, between 7 and 22 over the grid.
double ground(double x, double z) { return 14.0 + 6.0 * std::sin(0.11 * x + 0.3) * std::cos(0.13 * z) + 0.05 * x; }

constexpr int kWidth = 40, kDepth = 36, kTop = 32;
constexpr int kOriginX = -5, kOriginZ = 3;

// Pixel (i, j) holds f at its centre, world (origin + i + 0.5, origin + j + 0.5), normalised to
// [0, 1] over the height range [0, kTop].
std::vector<double> groundPixels(double voxelsPerPixel = 1.0) {
    std::vector<double> v;
    for (int j = 0; j < kDepth; ++j)
        for (int i = 0; i < kWidth; ++i)
            v.push_back(ground(kOriginX + (i + 0.5) * voxelsPerPixel, kOriginZ + (j + 0.5) * voxelsPerPixel) / kTop);
    return v;
}

std::string heightmapProgram(const std::string& file, double voxelsPerPixel = 1.0) {
    const int w = int(kWidth * voxelsPerPixel), d = int(kDepth * voxelsPerPixel);
    return fmt::format(R"(world {{ size = [{0}, {1}, {2}]; origin = [{3}, 0, {4}]; }}
heightmap ridge {{ file = "{5}"; origin = [{3}, {4}]; size = [{0}, {2}]; height = [0, {1}]; }}
field ground = clamp(ridge(wx, wz) - wy + 0.5, 0, 1);
pipeline {{ start; set ground; }}
)",
                       w, kTop, d, kOriginX, kOriginZ, file);
}

// Each column's density sum is the sampled height + 0.5 (the ramp is linear and inside the grid).
void expectColumnsFollowTheGround(const Program& program, double voxelsPerPixel = 1.0) {
    const DenseGrid grid = interpret(program);
    const glm::ivec3 size = program.world.size;
    double worst = 0.0;
    for (int z = 0; z < size.z; ++z)
        for (int x = 0; x < size.x; ++x) {
            double sum = 0.0;
            for (int y = 0; y < size.y; ++y) sum += grid.at({x, y, z});
            const double wx = kOriginX + x, wz = kOriginZ + z;
            // Past the outermost pixel centres the map is clamped: compare where it interpolates.
            const double half = 0.5 * voxelsPerPixel;
            if (wx < kOriginX + half || wz < kOriginZ + half || wx > kOriginX + size.x - half ||
                wz > kOriginZ + size.z - half)
                continue;
            worst = std::max(worst, std::abs(sum - 0.5 - ground(wx, wz)));
        }
    EXPECT_LE(worst, 0.5);
    EXPECT_GT(worst, 0.0); // the comparison ran
}

TEST(Heightmap, SixteenBitPngRoundTrips) {
    const fs::path dir = scratch();
    std::vector<uint16_t> pixels;
    for (double v : groundPixels()) pixels.push_back(uint16_t(std::lround(v * 65535.0)));
    test::writeBytes(dir / "ridge16.png", test::greyPng(kWidth, kDepth, pixels, 16));
    const CheckResult result = checkAt(dir / "a.vox", heightmapProgram("ridge16.png"));
    ASSERT_TRUE(result.program) << result.rendered();
    EXPECT_TRUE(result.diagnostics.empty()) << result.rendered();
    ASSERT_EQ(result.program->inputs.size(), 1u);
    EXPECT_EQ(result.program->inputs[0].path, (dir / "ridge16.png").string());
    EXPECT_FALSE(result.program->inputs[0].outside);
    expectColumnsFollowTheGround(*result.program);
}

TEST(Heightmap, EightBitPngRoundTrips) {
    const fs::path dir = scratch();
    std::vector<uint16_t> pixels;
    for (double v : groundPixels()) pixels.push_back(uint16_t(std::lround(v * 255.0)));
    test::writeBytes(dir / "ridge8.png", test::greyPng(kWidth, kDepth, pixels, 8));
    const CheckResult result = checkAt(dir / "a.vox", heightmapProgram("ridge8.png"));
    ASSERT_TRUE(result.program) << result.rendered();
    expectColumnsFollowTheGround(*result.program);
}

TEST(Heightmap, PixelsSpanningTwoVoxelsRoundTrip) {
    const fs::path dir = scratch();
    std::vector<uint16_t> pixels;
    for (double v : groundPixels(2.0)) pixels.push_back(uint16_t(std::lround(v * 65535.0)));
    test::writeBytes(dir / "coarse.png", test::greyPng(kWidth, kDepth, pixels, 16));
    const CheckResult result = checkAt(dir / "a.vox", heightmapProgram("coarse.png", 2.0));
    ASSERT_TRUE(result.program) << result.rendered();
    expectColumnsFollowTheGround(*result.program, 2.0);
}

TEST(Heightmap, NpyFloatAndUint16AndFloatTiffRoundTrip) {
    const fs::path dir = scratch();
    std::vector<float> floats;
    std::vector<uint16_t> words;
    for (double v : groundPixels()) floats.push_back(float(v)), words.push_back(uint16_t(std::lround(v * 65535.0)));
    const std::string shape = fmt::format("({}, {})", kDepth, kWidth);
    test::writeBytes(dir / "f.npy", test::npy("<f4", shape, test::bytesOf(floats)));
    test::writeBytes(dir / "u.npy", test::npy("<u2", shape, test::bytesOf(words)));
    test::floatTiff(dir / "f.tif", kWidth, kDepth, floats);
    for (const char* name : {"f.npy", "u.npy", "f.tif"}) {
        SCOPED_TRACE(name);
        const CheckResult result = checkAt(dir / "a.vox", heightmapProgram(name));
        ASSERT_TRUE(result.program) << result.rendered();
        expectColumnsFollowTheGround(*result.program);
    }
}

// ---- meshes ----

struct MeshCase {
    std::string file;
    std::string keys;                             // the block's other keys
    std::function<double(glm::dvec3)> distance;   // analytic signed distance of the solid
};

// Every voxel farther than one voxel from the analytic surface: solid exactly where the mesh's
// signed distance is negative. `warning`: the one diagnostic expected, at the file value.
void expectSignsAgree(const fs::path& dir, const MeshCase& c, const std::string& warning = "") {
    const std::string text = fmt::format(R"(world {{ size = [40, 36, 38]; origin = [-3, 2, 1]; }}
mesh rock {{ file = "{}"; {} }}
field inside = rock(wp) < 0 ? 1.0 : 0.0;
pipeline {{ start; set inside; }}
)",
                                         c.file, c.keys);
    const CheckResult result = checkAt(dir / "m.vox", text);
    ASSERT_TRUE(result.program) << result.rendered();
    if (warning.empty()) {
        EXPECT_TRUE(result.diagnostics.empty()) << result.rendered();
    } else {
        ASSERT_EQ(result.diagnostics.size(), 1u) << result.rendered();
        EXPECT_EQ(result.diagnostics[0].code, warning);
        EXPECT_EQ(result.diagnostics[0].loc.line, 2u);
        EXPECT_EQ(result.diagnostics[0].loc.column, 20u); // `mesh rock { file = ` is 19 characters
    }
    const DenseGrid grid = interpret(*result.program);
    size_t compared = 0, inside = 0, wrong = 0;
    for (int z = 0; z < 38; ++z)
        for (int y = 0; y < 36; ++y)
            for (int x = 0; x < 40; ++x) {
                const double d = c.distance(glm::dvec3(x - 3, y + 2, z + 1));
                if (std::abs(d) <= 1.0) continue;
                ++compared;
                inside += d < 0;
                wrong += (grid.at({x, y, z}) >= 0.5f) != (d < 0);
            }
    EXPECT_EQ(wrong, 0u);
    EXPECT_GT(inside, 300u);
    EXPECT_GT(compared, 40000u);
}

TEST(Mesh, SphereSignsAgreeInEveryFormat) {
    const fs::path dir = scratch();
    const test::Shape sphere = test::icosphere(1.0f, 3);
    test::writeBytes(dir / "ball.glb", test::glb(sphere));
    test::writeBytes(dir / "ball.obj", test::obj(sphere));
    test::writeBytes(dir / "ball.ply", test::ply(sphere));
    const glm::dvec3 centre(17.2, 19.7, 18.4);
    for (const char* file : {"ball.glb", "ball.obj", "ball.ply"}) {
        SCOPED_TRACE(file);
        expectSignsAgree(dir, {file, "translate = [17.2, 19.7, 18.4]; scale = 9.5;",
                               [&](glm::dvec3 p) { return glm::length(p - centre) - 9.5; }});
    }
}

TEST(Mesh, RotatedBoxSignsAgree) {
    const fs::path dir = scratch();
    test::writeBytes(dir / "box.glb", test::glb(test::box({-6, -4, -5}, {6, 4, 5})));
    // World = translate + R_y(30°) · p: the analytic box in the mesh's own frame.
    const glm::dvec3 centre(16.5, 18.0, 20.0);
    const double a = glm::radians(30.0);
    expectSignsAgree(dir, {"box.glb", "translate = [16.5, 18, 20]; rotate = [0, 30, 0]; band = 3;", [&](glm::dvec3 p) {
                               const glm::dvec3 q = p - centre;
                               const glm::dvec3 local(std::cos(a) * q.x - std::sin(a) * q.z, q.y,
                                                      std::sin(a) * q.x + std::cos(a) * q.z);
                               const glm::dvec3 e = glm::abs(local) - glm::dvec3(6, 4, 5);
                               return glm::length(glm::max(e, 0.0)) + std::min(std::max({e.x, e.y, e.z}), 0.0);
                           }});
}

// A box's analytic signed distance about `centre`, half extents `half`.
double boxDistance(glm::dvec3 p, glm::dvec3 centre, glm::dvec3 half) {
    const glm::dvec3 e = glm::abs(p - centre) - half;
    return glm::length(glm::max(e, 0.0)) + std::min(std::max({e.x, e.y, e.z}), 0.0);
}

test::Shape insideOut(test::Shape shape) {
    for (glm::uvec3& t : shape.triangles) std::swap(t.y, t.z);
    return shape;
}

test::Shape joined(test::Shape a, const test::Shape& b) {
    const uint32_t offset = uint32_t(a.points.size());
    a.points.insert(a.points.end(), b.points.begin(), b.points.end());
    for (const glm::uvec3& t : b.triangles) a.triangles.push_back(t + offset);
    return a;
}

// A closed mesh wound clockwise seen from outside: warned about (W0213 with its volume) at the
// file value, and signed as the solid all the same (the sign rule does not read the winding).
TEST(Mesh, AnInsideOutMeshIsWarnedAboutAndSignedAsItsSolid) {
    const fs::path dir = scratch();
    test::writeBytes(dir / "crate.obj", test::obj(insideOut(test::box({-6, -4, -5}, {6, 4, 5}))));
    expectSignsAgree(dir, {"crate.obj", "translate = [16.5, 18, 20]; band = 3;",
                           [](glm::dvec3 p) { return boxDistance(p, {16.5, 18, 20}, {6, 4, 5}); }},
                     "W0213");
    const CheckResult result = checkAt(dir / "m.vox", "world { size = [32, 32, 32]; }\n"
                                                      "mesh crate { file = \"crate.obj\"; }\n"
                                                      "field f = crate(wp) < 0 ? 1.0 : 0.0;\npipeline { start; set f; }\n");
    ASSERT_EQ(result.diagnostics.size(), 1u) << result.rendered();
    EXPECT_NE(result.diagnostics[0].message.find("1 closed part is wound clockwise seen from outside (signed volume "
                                                 "-960 cubic voxels)"),
              std::string::npos)
        << result.diagnostics[0].message;
}

// Each closed part is judged alone: an outward box beside an inside-out one is one part inside
// out; the inner wall of a hollow (wound inward, inside an outward part's box) and outward parts
// are none.
TEST(Mesh, InsideOutPartsAreCountedOneByOne) {
    const fs::path dir = scratch();
    const test::Shape outer = test::box({0, 0, 0}, {10, 10, 10});
    const test::Shape far = test::box({14, 0, 0}, {18, 4, 4});
    const struct {
        std::string file;
        test::Shape shape;
        size_t insideOutParts; // 0: no diagnostic
    } cases[] = {
        {"pair.obj", joined(outer, insideOut(far)), 1},
        {"both.ply", joined(insideOut(outer), insideOut(far)), 2},
        {"hollow.obj", joined(outer, insideOut(test::box({3, 3, 3}, {7, 7, 7}))), 0},
        {"apart.obj", joined(outer, far), 0},
    };
    for (const auto& c : cases) {
        test::writeBytes(dir / c.file, c.file.ends_with(".ply") ? test::ply(c.shape) : test::obj(c.shape));
        const CheckResult result = checkAt(dir / "m.vox", "world { size = [32, 32, 32]; }\nmesh m { file = \"" + c.file +
                                                              "\"; translate = [4, 4, 4]; }\n"
                                                              "field f = m(wp) < 0 ? 1.0 : 0.0;\npipeline { start; set f; }\n");
        ASSERT_TRUE(result.program) << c.file << "\n" << result.rendered();
        if (c.insideOutParts == 0) {
            EXPECT_TRUE(result.diagnostics.empty()) << c.file << "\n" << result.rendered();
            continue;
        }
        ASSERT_EQ(result.diagnostics.size(), 1u) << c.file << "\n" << result.rendered();
        EXPECT_EQ(result.diagnostics[0].code, "W0213");
        const std::string parts = c.insideOutParts == 1 ? "1 closed part is" : fmt::format("{} closed parts are", c.insideOutParts);
        EXPECT_NE(result.diagnostics[0].message.find(parts), std::string::npos) << result.diagnostics[0].message;
    }
}

// Two closed boxes that pass through each other, as models built of parts often are: warned about
// (W0214, naming the crossing pairs) at the file value, and signed as the union of the two solids.
TEST(Mesh, ASelfIntersectingMeshIsWarnedAboutAndSignedAsTheUnion) {
    const fs::path dir = scratch();
    test::writeBytes(dir / "parts.glb", test::glb(joined(test::box({-8, -5, -6}, {2, 5, 6}), test::box({-2, -4, -4}, {8, 4, 4}))));
    const glm::dvec3 centre(16.5, 18, 20);
    expectSignsAgree(dir, {"parts.glb", "translate = [16.5, 18, 20]; band = 3;",
                           [&](glm::dvec3 p) {
                               return std::min(boxDistance(p, centre + glm::dvec3(-3, 0, 0), {5, 5, 6}),
                                               boxDistance(p, centre + glm::dvec3(3, 0, 0), {5, 4, 4}));
                           }},
                     "W0214");
    const CheckResult result = checkAt(dir / "m.vox", "world { size = [32, 32, 32]; }\n"
                                                      "mesh parts { file = \"parts.glb\"; translate = [16, 16, 16]; }\n"
                                                      "field f = parts(wp) < 0 ? 1.0 : 0.0;\npipeline { start; set f; }\n");
    ASSERT_EQ(result.diagnostics.size(), 1u) << result.rendered();
    // Box B's four long faces (8 triangles) pass through box A's x = 2 face (2 triangles); each of
    // B's triangles there crosses one or both of A's.
    EXPECT_NE(result.diagnostics[0].message.find("pairs of triangles cross (the first: triangles "), std::string::npos)
        << result.diagnostics[0].message;
}

TEST(Mesh, AnOpenMeshIsWarnedAboutAtItsFile) {
    const fs::path dir = scratch();
    test::Shape open = test::box({-6, -4, -5}, {6, 4, 5});
    open.triangles.resize(10); // one face missing
    test::writeBytes(dir / "open.obj", test::obj(open));
    const CheckResult result =
        checkAt(dir / "m.vox", "world { size = [32, 32, 32]; }\nmesh shell { file = \"open.obj\"; translate = [16, 16, 16]; }\n"
                               "field f = shell(wp) < 0 ? 1.0 : 0.0;\npipeline { start; set f; }\n");
    ASSERT_TRUE(result.program) << result.rendered();
    ASSERT_EQ(result.diagnostics.size(), 1u) << result.rendered();
    EXPECT_EQ(result.diagnostics[0].code, "W0212");
    EXPECT_EQ(result.diagnostics[0].loc.line, 2u);
    EXPECT_EQ(result.diagnostics[0].loc.column, 21u);
    EXPECT_NE(result.diagnostics[0].message.find("4 edges border one triangle"), std::string::npos)
        << result.diagnostics[0].message;
    // The documented rule: what lies outside the box stays outside; its inside may be read as
    // outside through the hole (here it is: the exterior trace gets in).
    const DenseGrid grid = interpret(*result.program);
    size_t wrong = 0, outside = 0;
    for (int z = 0; z < 32; ++z)
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) {
                const glm::dvec3 e = glm::abs(glm::dvec3(x, y, z) - 16.0) - glm::dvec3(6, 4, 5);
                const double d = glm::length(glm::max(e, 0.0)) + std::min(std::max({e.x, e.y, e.z}), 0.0);
                if (std::abs(d) <= 1.0) continue;
                if (d < 0) continue;
                ++outside;
                wrong += grid.at({x, y, z}) >= 0.5f;
            }
    EXPECT_EQ(wrong, 0u);
    EXPECT_GT(outside, 20000u);
}

// ---- malformed files: each a located error at the `file` value ----

struct Malformed {
    std::string name;  // test name
    std::string block; // heightmap or mesh
    std::string file;
    std::string bytes;
    std::string code;
    std::string words; // in the message
};

std::vector<Malformed> malformedCases() {
    const std::string png16 = test::greyPng(8, 8, std::vector<uint16_t>(64, 1000), 16);
    const std::string glbBall = test::glb(test::icosphere(4.0f, 1));
    std::vector<float> withNan(64, 0.5f);
    withNan[19] = std::nanf("");
    const std::string plyBall = test::ply(test::icosphere(4.0f, 1));
    // A .gltf whose one buffer is a file beside it, as many exporters write by default.
    const std::string gltfExternal = R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 48, "uri": "rock.bin"}]})";
    return {
        {"TruncatedPng", "heightmap", "t.png", png16.substr(0, png16.size() / 2), "E0102", "truncated"},
        {"RgbPng", "heightmap", "rgb.png", test::rgbPng(4, 4), "E0010", "greyscale"},
        {"NotAnImage", "heightmap", "x.png", "hello, world", "E0102", "not a height image"},
        {"TruncatedNpy", "heightmap", "t.npy", test::npy("<f4", "(8, 8)", std::string(100, '\0')), "E0102", "truncated"},
        {"NpyOfDoubles", "heightmap", "d.npy", test::npy("<f8", "(8, 8)", std::string(512, '\0')), "E0010", "'<f8'; a height image is float32 ('<f4') or uint16 ('<u2'): save it with numpy as array.astype(numpy.float32)"},
        {"NpyWithNan", "heightmap", "n.npy", test::npy("<f4", "(8, 8)", test::bytesOf(withNan)), "E0102", "pixel (3, 2)"},
        {"TruncatedTiff", "heightmap", "t.tif", std::string("II*\0\x08\0\0\0\x20\0", 10), "E0102", "TIFF"},
        {"GlbMissingItsBuffer", "mesh", "b.glb", test::glb(test::icosphere(4.0f, 1), true), "E0102",
         "no BIN chunk, but its JSON names a buffer"},
        {"TruncatedGlb", "mesh", "t.glb", glbBall.substr(0, glbBall.size() - 40), "E0102",
         fmt::format("holds {} bytes where its header says {} (truncated)", glbBall.size() - 40, glbBall.size())},
        {"GlbCutInItsHeader", "mesh", "h.glb", glbBall.substr(0, 14), "E0102", "ends inside its 20-byte header"},
        {"GltfWithAnExternalBuffer", "mesh", "e.gltf", gltfExternal, "E0010", "external file 'rock.bin'"},
        {"NotAMesh", "mesh", "x.glb", "hello, world", "E0102", "glTF"},
        {"NanVertex", "mesh", "n.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n", "E0102", "not finite"},
        {"ObjIndexOutOfRange", "mesh", "i.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "E0102", "does not exist"},
        {"ObjWithoutFaces", "mesh", "e.obj", "v 0 0 0\n", "E0102", "no triangles"},
        {"TruncatedPly", "mesh", "t.ply", plyBall.substr(0, plyBall.size() - 7), "E0102", "truncated"},
        {"PlyWithoutHeader", "mesh", "h.ply", "ply\nformat ascii 1.0\n", "E0102", "end_header"},
        {"NotAMeshExtension", "mesh", "rock.png", png16, "E0010", ".glb, .gltf, .obj, .ply"},
    };
}

class MalformedInput : public testing::TestWithParam<Malformed> {};

TEST_P(MalformedInput, IsALocatedErrorAtItsFileKey) {
    const Malformed& c = GetParam();
    const fs::path dir = scratch();
    test::writeBytes(dir / c.file, c.bytes);
    const std::string keys = c.block == "heightmap" ? "height = [0, 8];" : "";
    const std::string sample = c.block == "heightmap" ? "src(wx, wz) - wy" : "src(wp)";
    const CheckResult result =
        checkAt(dir / "bad.vox", fmt::format("world {{ size = [16, 16, 16]; }}\n{} src {{ file = \"{}\"; {} }}\n"
                                             "field f = clamp({}, 0, 1);\npipeline {{ start; set f; }}\n",
                                             c.block, c.file, keys, sample));
    EXPECT_FALSE(result.program);
    ASSERT_EQ(result.diagnostics.size(), 1u) << result.rendered();
    const Diagnostic& d = result.diagnostics[0];
    EXPECT_EQ(d.code, c.code) << d.message;
    EXPECT_EQ(d.loc.line, 2u);
    EXPECT_EQ(d.loc.column, uint32_t(c.block.size() + 15)) << result.rendered();
    EXPECT_NE(d.message.find(c.words), std::string::npos) << d.message;
}

INSTANTIATE_TEST_SUITE_P(Inputs, MalformedInput, testing::ValuesIn(malformedCases()),
                         [](const testing::TestParamInfo<Malformed>& info) { return info.param.name; });

TEST(Inputs, AMissingFileIsE0100AtItsFileKey) {
    const CheckResult result = checkAt(scratch() / "a.vox", "world { size = [8, 8, 8]; }\n"
                                                           "heightmap h { file = \"nowhere.png\"; height = [0, 4]; }\n");
    ASSERT_EQ(result.diagnostics.size(), 1u) << result.rendered();
    EXPECT_EQ(result.diagnostics[0].code, "E0100");
    EXPECT_EQ(result.diagnostics[0].loc.line, 2u);
    EXPECT_EQ(result.diagnostics[0].loc.column, 22u);
}

TEST(Inputs, LimitsAreE0012AtTheFileKey) {
    const fs::path dir = scratch();
    test::writeBytes(dir / "big.png", test::greyPng(64, 64, std::vector<uint16_t>(64 * 64, 7), 16));
    test::writeBytes(dir / "ball.ply", test::ply(test::icosphere(1.0f, 2)));
    test::writeBytes(dir / "small.ply", test::ply(test::icosphere(1.0f, 0)));
    const std::string text = "world { size = [8, 8, 8]; }\n"
                             "heightmap h { file = \"big.png\"; height = [0, 4]; }\n"
                             "mesh m { file = \"ball.ply\"; scale = 3; }\n"
                             "mesh huge { file = \"small.ply\"; scale = 400; }\n";
    Limits limits;
    limits.maxImagePixels = 1000;
    limits.maxMeshTriangles = 100;
    const CheckResult result = checkAt(dir / "a.vox", text, limits);
    ASSERT_EQ(result.diagnostics.size(), 3u) << result.rendered();
    for (const Diagnostic& d : result.diagnostics) EXPECT_EQ(d.code, "E0012") << d.message;
    EXPECT_EQ(result.diagnostics[0].loc.line, 2u);
    EXPECT_NE(result.diagnostics[0].message.find("64 x 64 pixels"), std::string::npos);
    EXPECT_EQ(result.diagnostics[1].loc.line, 3u);
    EXPECT_NE(result.diagnostics[1].message.find("limit of 100 triangles"), std::string::npos);
    EXPECT_EQ(result.diagnostics[2].loc.line, 4u);
    EXPECT_NE(result.diagnostics[2].message.find("signed-distance grid"), std::string::npos);
}

TEST(Inputs, SamplingWithTheWrongArgumentsIsLocated) {
    const fs::path dir = scratch();
    test::writeBytes(dir / "h.png", test::greyPng(4, 4, std::vector<uint16_t>(16, 7), 8));
    test::writeBytes(dir / "ball.obj", test::obj(test::icosphere(2.0f, 1)));
    const CheckResult result =
        checkAt(dir / "a.vox", "world { size = [8, 8, 8]; }\n"
                               "heightmap h { file = \"h.png\"; height = [0, 4]; }\n"
                               "mesh m { file = \"ball.obj\"; }\n"
                               "field f = h(wp) + m(wx, wz) + m(wx);\n");
    ASSERT_EQ(result.diagnostics.size(), 3u) << result.rendered();
    EXPECT_EQ(result.diagnostics[0].code, "E0006");
    EXPECT_EQ(result.diagnostics[1].code, "E0006");
    EXPECT_EQ(result.diagnostics[2].code, "E0010");
}

// A compiled package keeps copies of its input files (hashed in the manifest) and loads from
// them with the originals gone, to the same voxels.
TEST(Inputs, APackageKeepsItsInputFilesAndLoadsWithoutThem) {
    const fs::path dir = scratch() / "package";
    fs::create_directories(dir);
    std::vector<uint16_t> pixels;
    for (double v : groundPixels()) pixels.push_back(uint16_t(std::lround(v * 65535.0)));
    test::writeBytes(dir / "ridge.png", test::greyPng(kWidth, kDepth, pixels, 16));
    test::writeBytes(dir / "ball.obj", test::obj(test::icosphere(6.0f, 2)));
    std::string text = heightmapProgram("ridge.png");
    text.erase(text.find("pipeline")); // its own pipeline follows
    text += "mesh ball { file = \"ball.obj\"; translate = [10, 18, 20]; }\n"
                                                             "field rock = clamp(0.5 - ball(wp), 0, 1);\n"
                                                             "pipeline { start; set ground; union rock; }\n";
    test::writeBytes(dir / "scene.vox", text);
    const CheckResult checked = checkFile((dir / "scene.vox").string());
    ASSERT_TRUE(checked.program) << checked.rendered();
    ASSERT_EQ(checked.program->inputs.size(), 2u);
    const codegen::PackageSource source =
        packageSource((dir / "scene.vox").string(), checked.source.text(), checked.lsystems, checked.program->inputs);
    ASSERT_EQ(source.imports.size(), 2u);
    EXPECT_EQ(source.imports[0].path, "ridge.png");
    EXPECT_EQ(source.imports[1].path, "ball.obj");
    const fs::path packageDir = dir / "pkg";
    codegen::writePackage(compileProgram(*checked.program), packageDir.string(), source);
    EXPECT_EQ(test::readBytes(packageDir / "sources/1.png"), test::readBytes(dir / "ridge.png"));
    EXPECT_EQ(test::readBytes(packageDir / "sources/2.obj"), test::readBytes(dir / "ball.obj"));
    const std::string manifest = test::readBytes(packageDir / "manifest.json");
    EXPECT_NE(manifest.find("\"path\": \"ridge.png\""), std::string::npos) << manifest;
    EXPECT_NE(manifest.find("\"file\": \"sources/2.obj\""), std::string::npos) << manifest;
    fs::remove(dir / "ridge.png");
    fs::remove(dir / "ball.obj");
    const LoadedPackage loaded = loadPackage(packageDir.string());
    EXPECT_EQ(interpret(loaded.program).data(), interpret(*checked.program).data());
}

} // namespace inputs_test
} // namespace voxc
