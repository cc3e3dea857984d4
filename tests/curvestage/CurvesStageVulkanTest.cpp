// The curves stage on lavapipe against the interpreter: densities and materials bit-identical
// for every mode at chunk sizes 8, 16 and 32, at the origin and at an odd negative one, and the
// planes program likewise.
#include "CheckedProgram.h"
#include "Lavapipe.h"
#include "GridCompare.h"
#include "Programs.h"

#include "voxc/check/Check.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Solve.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"

#include <gtest/gtest.h>

namespace voxc {
namespace {

// Solved once here, so the interpreter and the three chunk sizes' runs combine the same table.
Program checked(const std::string& text) {
    Program program = test::checkedProgram("curves.vox", text, test::Allowed::None);
    stages::solveBlocks(program);
    return program;
}

void expectDeviceMatches(const Program& program) {
    test::expectLavapipeMatchesAtEveryChunkSize(program, interpret(program));
}

TEST(vulkan_CurvesStage, EveryModeMatchesTheInterpreter) {
    for (const char* world : {"", "origin = [-13, -6, 5];"})
        for (const char* mode : {"set", "union", "subtract", "intersect"}) {
            SCOPED_TRACE(fmt::format("{} '{}'", mode, world));
            expectDeviceMatches(checked(test::ridgeProgram(mode, world)));
        }
}

// A set over a box smaller than the grid keeps what the stages before it wrote outside the box
// (here a start state without materials, which nothing else keeps alive).
TEST(vulkan_CurvesStage, SetKeepsTheGridOutsideItsBox) {
    const Program program = checked(test::ridgeProgram("set", "", false));
    const DenseGrid expected = interpret(program);
    EXPECT_EQ(expected.at({0, 0, 0}), 1.0f); // the start's rock, outside the box
    expectDeviceMatches(program);
}

// A curves stage among others: a field carves a tunnel through the solved ridge, a grammar
// crumbles the rock under overhangs, and a second curves stage is intersected at the end.
TEST(vulkan_CurvesStage, AmongFieldsAndGrammarsMatchesTheInterpreter) {
    std::string text = test::ridgeProgram("union", "origin = [5, -3, -11];");
    text.replace(text.find("pipeline {"), std::string::npos, R"(
field tunnel = clamp(4 - length(p.xy - vec2(18, 8)), 0, 1);
grammar crumble {
  rule thin {
    size = [1, 3, 1];
    probability = 0.5;
    symbol { [GEQ 0.5] [GEQ 0.5] [LT 0.5] }
    transform { [NOP] [ADD -0.5] [NOP] }
  }
}
pipeline { start; union ridge; subtract tunnel material rock; crumble; intersect ridge; }
)");
    expectDeviceMatches(checked(text));
}

TEST(vulkan_CurvesStage, PlaneMatchesTheInterpreter) {
    expectDeviceMatches(checked(test::planeProgram(glm::normalize(glm::dvec3(1, 2, 0.5)), {15.5, 11.3, 16.25}, {32, 24, 32})));
}

} // namespace
} // namespace voxc
