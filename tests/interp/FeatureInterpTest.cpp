// Dey's generators (`feature` blocks) through the interpreter: the shapes they promise and that
// every key of every generator changes the voxels.
#include "CheckedProgram.h"
#include "voxc/check/Check.h"
#include "voxc/interp/FieldEval.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/stages/Pipeline.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstring>

namespace voxc {
namespace feature_interp_test {

const std::string kWorld = "world { size = [64, 64, 64]; seed = 5; }\n";

Program checked(const std::string& text) { return test::checkedProgram("test.vox", text); }

// The feature's density (1 rock, 0 air) at one voxel of a 64^3 grid.
float densityAt(const std::string& feature, glm::ivec3 voxel) {
    const Program program = checked(kWorld + "feature f = " + feature);
    if (program.fields.empty()) return -1.0f;
    return FieldEvaluator(program.fields.back(), program.world.origin).density(voxel);
}

// The whole grid after `start; union f;`.
DenseGrid voxels(const std::string& feature) {
    return interpret(checked(kWorld + "feature f = " + feature + "\npipeline { start; union f; }"));
}

bool sameVoxels(const DenseGrid& a, const DenseGrid& b) {
    const glm::ivec3 size = a.size();
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const float u = a.at({x, y, z}), v = b.at({x, y, z});
                if (std::memcmp(&u, &v, sizeof(float)) != 0) return false;
            }
    return true;
}

int rockVoxels(const DenseGrid& grid, int zMin, int zMax) {
    int count = 0;
    const glm::ivec3 size = grid.size();
    for (int z = zMin; z < zMax; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) count += grid.at({x, y, z}) >= 0.5f;
    return count;
}

TEST(interp_Features, ArchEndsAreRockAndItsSpanIsOpenBelowTheApex) {
    const std::string arch = "arch { start = [12, 8, 32]; end = [52, 8, 32]; peak = 10; radius = 3; }";
    EXPECT_EQ(densityAt(arch, {12, 8, 32}), 1.0f);
    EXPECT_EQ(densityAt(arch, {52, 8, 32}), 1.0f);
    // Both control points rise by 10, so the apex is 7.5 above the ends at x = 32.
    EXPECT_EQ(densityAt(arch, {32, 15, 32}), 1.0f);
    for (int y = 0; y <= 10; ++y) EXPECT_EQ(densityAt(arch, {32, y, 32}), 0.0f) << "y = " << y;
}

TEST(interp_Features, ArchIsThickerAtItsEndsThanAtItsMiddle) {
    // Defaults: taper_radius 1 and taper_interpolant 0 double the radius at the ends.
    const std::string arch = "arch { start = [12, 8, 32]; end = [52, 8, 32]; peak = 10; radius = 4; }";
    EXPECT_EQ(densityAt(arch, {12, 8, 32 + 7}), 1.0f); // within 2r = 8 of the end
    EXPECT_EQ(densityAt(arch, {32, 15, 32 + 7}), 0.0f); // farther than r = 4 from the apex
}

TEST(interp_Features, CaveMouthIsOpenAtItsStartAndDecayShrinksIt) {
    const std::string cave = "cave { start = [32, 32, 4]; gravity = 0; mouth = 6; decay = 0.5; }";
    EXPECT_EQ(densityAt(cave, {32, 32, 4}), 1.0f); // carved: the field is 1 where it removes rock
    EXPECT_EQ(densityAt(cave, {32, 37, 5}), 1.0f); // the mouth is wide
    // 20 steps of 1 along +z; at the end the radius is 6 - 20 * 0.5 * 6 / 20 = 3.
    EXPECT_EQ(densityAt(cave, {32, 32, 24}), 1.0f);
    EXPECT_EQ(densityAt(cave, {32, 37, 23}), 0.0f);
    EXPECT_EQ(densityAt(cave, {32, 32, 30}), 0.0f);
    // More decay carves less rock.
    const DenseGrid wide = voxels("cave { start = [32, 32, 4]; decay = 0.1; }");
    const DenseGrid narrow = voxels("cave { start = [32, 32, 4]; decay = 0.9; }");
    EXPECT_GT(rockVoxels(wide, 0, 64), rockVoxels(narrow, 0, 64));
}

TEST(interp_Features, CaveSinksUnderGravity) {
    const std::string cave = "cave { start = [32, 40, 4]; mouth = 2; gravity = 1; }";
    // After 20 steps the particle has fallen sum_{t<20} t/20 = 9.5 voxels.
    EXPECT_EQ(densityAt(cave, {32, 30, 24}), 1.0f);
    EXPECT_EQ(densityAt(cave, {32, 40, 24}), 0.0f);
}

TEST(interp_Features, OverhangFillsItsBoxUnderTheSurface) {
    const std::string cliff = "overhang { min = [8, 0, 8]; max = [40, 48, 56]; }";
    // Defaults: the top and the base reach the full depth in the middle of the face (u = 0.5).
    EXPECT_EQ(densityAt(cliff, {12, 47, 32}), 1.0f);
    EXPECT_EQ(densityAt(cliff, {12, 0, 32}), 1.0f);
    EXPECT_EQ(densityAt(cliff, {36, 24, 32}), 0.0f); // the undercut between them
    EXPECT_EQ(densityAt(cliff, {12, 48, 32}), 0.0f); // above the box
    EXPECT_EQ(densityAt(cliff, {4, 20, 32}), 0.0f);  // beside the box
    EXPECT_EQ(densityAt(cliff, {12, 20, 9}), 0.0f);  // the parabola closes the face's ends
}

// One key of one generator set away from a base block; the base's own setting of that key, if
// any, is dropped (a key may appear once).
struct Variation {
    std::string generator;
    std::vector<std::string> base; // "key = value;"
    std::string change;
};

void PrintTo(const Variation& v, std::ostream* out) { *out << v.generator << " " << v.change; }

std::string keyOf(const std::string& assignment) { return assignment.substr(0, assignment.find(' ')); }

std::string block(const Variation& v, bool changed) {
    std::string text = v.generator + " {";
    for (const std::string& assignment : v.base)
        if (!changed || keyOf(assignment) != keyOf(v.change)) text += " " + assignment;
    return text + (changed ? " " + v.change : std::string()) + " }";
}

class FeatureKeys : public ::testing::TestWithParam<Variation> {};

TEST_P(FeatureKeys, ChangingTheKeyChangesTheVoxels) {
    const Variation& v = GetParam();
    EXPECT_FALSE(sameVoxels(voxels(block(v, false)), voxels(block(v, true)))) << v.change;
}

const std::vector<std::string> kArch = {"start = [16, 16, 16];", "end = [48, 40, 24];", "taper_interpolant = 0.2;"};
const std::vector<std::string> kCave = {"start = [16, 30, 4];", "direction = [0.3, 0, 1];", "curl = 0.5;",
                                        "decay = 0.3;", "gravity = 0.5;", "gravity_exponent = 2;"};
const std::vector<std::string> kCliff = {"min = [8, 0, 8];", "max = [40, 48, 56];", "parabola_offset = 0.2;",
                                         "parabola_exponent = 2;"};

std::vector<Variation> variations() {
    std::vector<Variation> all;
    for (const char* change :
         {"start = [20, 16, 16];", "end = [44, 40, 24];", "iterations = 10;", "radius = 7;", "offset = 0.2;",
          "peak = 5;", "taper_interpolant = 0.6;", "taper_radius = 0.5;", "taper_exponent = 3;",
          "start_offset = 0.2;", "start_peak = 5;", "start_taper_interpolant = 0.6;", "start_taper_radius = 0.5;",
          "start_taper_exponent = 3;", "end_offset = 0.2;", "end_peak = 5;", "end_taper_interpolant = 0.6;",
          "end_taper_radius = 0.5;", "end_taper_exponent = 3;", "translate = [2, 0, 0];", "rotate = [0, 30, 0];"})
        all.push_back({"arch", kArch, change});
    for (const char* change :
         {"start = [20, 30, 4];", "direction = [0, 0, 1];", "iterations = 30;", "mouth = 7;", "curl = 1;",
          "decay = 0.6;", "gravity = 1;", "gravity_exponent = 1;", "translate = [0, 3, 0];", "rotate = [0, 20, 0];"})
        all.push_back({"cave", kCave, change});
    for (const char* change :
         {"lip_height = 0.5;", "base_depth = 0.5;", "top_erosion = 0.5;", "bottom_erosion = 0.5;",
          "parabola_offset = 0.6;", "parabola_exponent = 3;", "min = [4, 0, 8];", "max = [40, 40, 56];",
          "translate = [3, 0, 0];", "rotate = [0, 10, 0];"})
        all.push_back({"overhang", kCliff, change});
    return all;
}

INSTANTIATE_TEST_SUITE_P(Generators, FeatureKeys, ::testing::ValuesIn(variations()), [](const auto& info) {
    return info.param.generator + "_" + keyOf(info.param.change);
});

} // namespace feature_interp_test
} // namespace voxc
