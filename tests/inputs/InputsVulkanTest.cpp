// Heightmap and mesh blocks on lavapipe against the interpreter: densities and materials bit for
// bit at chunk sizes 8, 16 and 32, at the origin and at odd negative and positive ones, with
// coordinates inside the maps, past their edges (clamped) and off the voxel lattice.
#include "CheckedProgram.h"
#include "GridCompare.h"
#include "InputFiles.h"
#include "Lavapipe.h"

#include "voxc/check/Check.h"
#include "voxc/stages/Pipeline.h"

#include <algorithm>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace voxc {
namespace {

namespace fs = std::filesystem;

fs::path inputsDir() {
    const fs::path dir = fs::temp_directory_path() / fmt::format("voxc_inputs_vulkan_{}", ::getpid());
    fs::create_directories(dir);
    std::vector<uint16_t> pixels;
    for (int j = 0; j < 27; ++j)
        for (int i = 0; i < 33; ++i)
            pixels.push_back(uint16_t(30000 + 20000 * std::sin(0.2 * i) * std::cos(0.25 * j) + 37 * i));
    test::writeBytes(dir / "ridge.png", test::greyPng(33, 27, pixels, 16));
    test::writeBytes(dir / "ball.glb", test::glb(test::icosphere(1.0f, 3)));
    test::writeBytes(dir / "box.ply", test::ply(test::box({-3, -2, -4}, {3, 2, 4})));
    return dir;
}

// A heightmap smaller than the grid (1.3 voxels a pixel, its corner inside the grid's), a boulder
// and a box placed on it, smoothly joined, a tunnel under the ground and a ledge sampled at
// warped coordinates.
std::string programAt(const fs::path& dir, glm::ivec3 origin) {
    const int x = origin.x + 4, z = origin.z + 3;
    return fmt::format(R"(
world {{ size = [37, 30, 29]; origin = [{0}, {1}, {2}]; seed = 3; }}
material rock {{ id = 1; }}
material sand {{ id = 2; }}
heightmap ridge {{ file = "{3}/ridge.png"; origin = [{4}, {5}]; size = [42.9, 35.1]; height = [{6}, {7}]; }}
mesh boulder {{ file = "{3}/ball.glb"; translate = [{8}, {9}, {10}]; scale = 6.5; band = 3; }}
mesh slab {{ file = "{3}/box.ply"; translate = [{11}, {9}, {10}]; rotate = [10, 35, -5]; scale = 1.5; }}
field ground = clamp(ridge(wx, wz) - wy + 0.5, 0, 1);
field rocks = clamp(0.5 - sdf_smooth_union(sdf_smooth_union(boulder(wp), slab(wp), 2), wy - ridge(wx, wz), 3), 0, 1);
field tunnel = clamp(3 - length(vec2(wy - (ridge(wx, wz) - 5), wx * 0.3 + wz * 0.1 - {12})), 0, 1);
field ledge = clamp(sdf_heightfield(wp, ridge(wx * 0.77 + 1.3, wz - 2.6) - 2) * -0.5, 0, 1);
pipeline {{ start; set ground material rock; union rocks material sand; subtract tunnel; union ledge material sand; }}
)",
                       origin.x, origin.y, origin.z, dir.string(), x, z, origin.y + 4, origin.y + 22, origin.x + 14,
                       origin.y + 18, origin.z + 15, origin.x + 26, (origin.x + origin.z) * 0.4 + 4);
}

// Checks `text`, requires the interpreter's grid to be a fifth to nine tenths solid (there is
// ground, and air) with more than least[m] voxels of each material m, then compares lavapipe with
// it at every chunk size.
void expectGroundOnBothBackends(const std::string& name, const std::string& text,
                                const std::vector<std::pair<uint8_t, long>>& least) {
    CheckResult result = checkSource(SourceFile(name, text));
    ASSERT_TRUE(result.program) << result.rendered();
    const DenseGrid expected = interpret(*result.program);
    size_t solid = 0;
    for (float d : expected.data()) solid += d >= 0.5f;
    EXPECT_GT(solid, expected.data().size() / 5);
    EXPECT_LT(solid, expected.data().size() * 9 / 10);
    for (const auto& [material, count] : least)
        EXPECT_GT(std::count(expected.materials().begin(), expected.materials().end(), material), count)
            << "material " << int(material);
    test::expectLavapipeMatchesAtEveryChunkSize(*result.program, expected);
}

TEST(vulkan_Inputs, HeightmapsAndMeshesMatchTheInterpreter) {
    const fs::path dir = inputsDir();
    for (const glm::ivec3 origin : {glm::ivec3(0), glm::ivec3(-13, -7, 5), glm::ivec3(9, 3, -21)}) {
        SCOPED_TRACE(fmt::format("origin {} {} {}", origin.x, origin.y, origin.z));
        expectGroundOnBothBackends("inputs.vox", programAt(dir, origin), {{2, 100}}); // rocks
    }
}

// The same heightmap and boulder as inputs of a curves block (docs/curves.md, "Heightmaps and
// meshes as inputs"), with a road curve cut across them: the solve runs on the host once, and
// both backends combine its table the same way.
std::string curvesInputsAt(const fs::path& dir, glm::ivec3 origin) {
    return fmt::format(R"(
world {{ size = [37, 30, 29]; origin = [{0}, {1}, {2}]; seed = 3; }}
material rock {{ id = 1; }}
material sand {{ id = 2; }}
heightmap ridge {{ file = "{3}/ridge.png"; origin = [{4}, {5}]; size = [42.9, 35.1]; height = [{6}, {7}]; }}
mesh boulder {{ file = "{3}/ball.glb"; translate = [{8}, {9}, {10}]; scale = 6.5; band = 3; }}
curves carved {{
  box = [[1, 0, 2], [35, 29, 26]];
  inputs = [ridge, boulder];
  dead_zone = 2;
  input_material = rock;
  input_amplitude = 0.5;
  curve road {{
    points = [[-2, 9, 6], [12, 11, 12], [24, 12, 16], [40, 10, 22]];
    constraint {{ t = 0; material = sand; amplitude = 0.4; }}
    constraint {{ t = 1; material = sand; }}
  }}
}}
pipeline {{ start; set carved; }}
)",
                       origin.x, origin.y, origin.z, dir.string(), origin.x + 4, origin.z + 3, origin.y + 4,
                       origin.y + 22, origin.x + 14, origin.y + 18, origin.z + 15);
}

TEST(vulkan_Inputs, CurvesWithHeightmapAndMeshInputsMatchTheInterpreter) {
    const fs::path dir = inputsDir();
    for (const glm::ivec3 origin : {glm::ivec3(0), glm::ivec3(-13, -7, 5)}) {
        SCOPED_TRACE(fmt::format("origin {} {} {}", origin.x, origin.y, origin.z));
        expectGroundOnBothBackends("curves_inputs.vox", curvesInputsAt(dir, origin), {{1, 100}, {2, 20}}); // inputs, road
    }
}

} // namespace
} // namespace voxc
