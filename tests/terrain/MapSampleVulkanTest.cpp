// A terrain's map sampled from fields on lavapipe against the interpreter: densities and
// materials bit-identical at chunk sizes 8, 16 and 32, at the origin and at odd negative ones,
// with coordinates inside the map, past its edges (clamped) and warped off the voxel grid.
#include "CheckedProgram.h"
#include "GridCompare.h"
#include "Lavapipe.h"

#include "voxc/check/Check.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>

namespace voxc {
namespace {

Program checked(const std::string& text) { return test::checkedProgram("map.vox", text, test::Allowed::None); }

// An eroded map smaller than the grid, its corner a little inside the grid's (so columns past
// both edges read the clamped edge), the ground from it, a tunnel that follows the ground 5
// voxels down and a ledge sampled at warped coordinates.
std::string programAt(glm::ivec3 origin) {
    const int x = origin.x + 5, z = origin.z + 3;
    return fmt::format(R"(
world {{ size = [37, 26, 29]; origin = [{0}, {1}, {2}]; seed = 3; }}
material rock {{ id = 1; }}
material sand {{ id = 2; }}
terrain hills {{
  origin = [{3}, {4}]; size = 24; levels = [2, 5]; max_height = 18;
  preset = mountain_river; steps_scale = 0.05;
  noise {{ amplitude = 2; scale = 4; }}
  spline crest {{ points = [[{5}, 14, {6}], [{7}, 16, {8}], [{9}, 10, {10}], [{11}, 12, {12}]]; radius = 2;
                  left = [6, -6]; right = [6, -6]; hardness = 0.2; }}
}}
field ground = clamp(hills(wx, wz) - wy + 0.5, 0, 1);
field tunnel = clamp(3 - length(vec2(wy - (hills(wx, wz) - 5), wx * 0.3 + wz * 0.1 - 4)), 0, 1);
field ledge = clamp(sdf_heightfield(wp, hills(wx * 0.77 + 1.3, wz - 2.6) - 2) * -0.5, 0, 1);
pipeline {{ start; set ground material rock; subtract tunnel; union ledge material sand; }}
)",
                       origin.x, origin.y, origin.z, x, z, x, z + 2, x + 8, z + 9, x + 16, z + 15, x + 24, z + 22);
}

TEST(vulkan_MapSample, FieldsSamplingAMapMatchTheInterpreter) {
    for (const glm::ivec3 origin : {glm::ivec3(0), glm::ivec3(-13, -7, 5), glm::ivec3(9, 3, -21)}) {
        SCOPED_TRACE(fmt::format("origin {} {} {}", origin.x, origin.y, origin.z));
        Program p = checked(programAt(origin));
        const DenseGrid expected = interpret(p);
        size_t solid = 0;
        for (float d : expected.data()) solid += d >= 0.5f;
        EXPECT_GT(solid, expected.data().size() / 5); // there is ground
        EXPECT_LT(solid, expected.data().size() * 9 / 10);
        // The ledge adds sand and the tunnel carves under the ground somewhere.
        EXPECT_GT(std::count(expected.materials().begin(), expected.materials().end(), uint8_t(2)), 100);
        size_t roofed = 0; // air under solid: the tunnel
        for (int z = 0; z < 29; ++z)
            for (int y = 0; y + 1 < 26; ++y)
                for (int x = 0; x < 37; ++x) roofed += expected.at({x, y, z}) < 0.5f && expected.at({x, y + 1, z}) >= 0.5f;
        EXPECT_GT(roofed, 20u);
        test::expectLavapipeMatchesAtEveryChunkSize(p, expected);
    }
}

} // namespace
} // namespace voxc
