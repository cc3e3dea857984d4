// Aggregate tests against a brute-force evaluation: a rule whose symbol is all IGN marks its
// anchor where its `where` test holds; windows tile the grid (stride = window), so every window
// reads the start state, which the test evaluates on its own. Then the same on Vulkan.
#include "CheckedProgram.h"
#include "GridCompare.h"
#include "Lavapipe.h"
#include "voxc/check/Check.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/stages/Pipeline.h"

#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <gtest/gtest.h>

namespace voxc {
namespace aggregates_test {

constexpr glm::ivec3 kWindow{3, 2, 3};
constexpr float kMark = 7.0f;

std::string program(const std::string& where) {
    return fmt::format(R"(
world {{ size = [36, 24, 33]; origin = [-5, 0, 8]; chunk = 16; seed = 3; }}
material rock {{ id = 1; color = [1, 1, 1]; }}
start {{
  fill {{ value = 0; }}
  heightfield {{ base = 11; amplitude = 6; frequency = 0.12; octaves = 3; material = rock; }}
  sphere {{ center = [18, 12, 16]; radius = 5; value = 0.3; }}
}}
grammar mark {{
  stride = [3, 2, 3];
  rule m {{
    size = [3, 2, 3];
    symbol {{ layer {{ [IGN, IGN, IGN] [IGN, IGN, IGN] }} layer {{ [IGN, IGN, IGN] [IGN, IGN, IGN] }}
             layer {{ [IGN, IGN, IGN] [IGN, IGN, IGN] }} }}
    transform {{ layer {{ [NOP, NOP, NOP] [SET 7, NOP, NOP] }} layer {{ [NOP, NOP, NOP] [NOP, NOP, NOP] }}
                layer {{ [NOP, NOP, NOP] [NOP, NOP, NOP] }} }}
    {}
  }}
}}
)",
                       where);
}

Program checked(const std::string& text) { return test::checkedProgram("aggregates.vox", text); }

// Whether the test holds for the window anchored at `anchor` (grid-local) of the start state.
using WindowTest = std::function<bool(const DenseGrid&, glm::ivec3 anchor)>;

void expectMarksWhere(const std::string& where, const WindowTest& holds) {
    SCOPED_TRACE(where);
    const Program marked = checked(program(where));
    const DenseGrid start = evaluateStart(marked);
    DenseGrid expected = start;
    int marks = 0, anchors = 0;
    const glm::ivec3 size = start.size();
    for (int z = 0; z + kWindow.z <= size.z; z += kWindow.z)
        for (int y = 0; y + kWindow.y <= size.y; y += kWindow.y)
            for (int x = 0; x + kWindow.x <= size.x; x += kWindow.x) {
                ++anchors;
                if (!holds(start, {x, y, z})) continue;
                expected.at({x, y, z}) = kMark; // SET 7 sits at the anchor (bottom row, first layer)
                ++marks;
            }
    // The test says something only if the aggregate separates windows.
    EXPECT_GT(marks, 5);
    EXPECT_LT(marks, anchors - 5);
    const DenseGrid interpreted = interpret(marked);
    EXPECT_EQ(test::countBitDifferences(expected, interpreted), 0u);
    EXPECT_EQ(test::countBitDifferences(interpreted, test::runOnLavapipe(marked)), 0u);
}

template <typename Visit>
void forBox(glm::ivec3 anchor, glm::ivec3 lo, glm::ivec3 hi, Visit&& visit) {
    for (int z = lo.z; z < hi.z; ++z)
        for (int y = lo.y; y < hi.y; ++y)
            for (int x = lo.x; x < hi.x; ++x) visit(anchor + glm::ivec3(x, y, z));
}

TEST(e2e_Aggregates, SolidFractionOverTheWindow) {
    expectMarksWhere("where { solid_fraction = [0.4, 0.8]; }", [](const DenseGrid& g, glm::ivec3 a) {
        int solid = 0;
        forBox(a, {0, 0, 0}, kWindow, [&](glm::ivec3 p) { solid += g.at(p) >= 0.5f; });
        return solid >= 8 && solid <= 14; // 0.4 * 18 = 7.2 -> 8; 0.8 * 18 = 14.4 -> 14
    });
}

TEST(e2e_Aggregates, MeanOverTheWindow) {
    expectMarksWhere("where { mean = [0.25, 0.75]; }", [](const DenseGrid& g, glm::ivec3 a) {
        double sum = 0.0;
        forBox(a, {0, 0, 0}, kWindow, [&](glm::ivec3 p) { sum += g.at(p); });
        const double mean = sum / 18.0;
        return mean >= 0.25 && mean <= 0.75;
    });
}

TEST(e2e_Aggregates, MinAndMaxOverABox) {
    expectMarksWhere("where top { box = [[0, 1, 0], [3, 2, 3]]; min = [0, 0.4]; max = [0.3, 1]; }",
                     [](const DenseGrid& g, glm::ivec3 a) {
                         float lo = INFINITY, hi = -INFINITY;
                         forBox(a, {0, 1, 0}, {3, 2, 3}, [&](glm::ivec3 p) {
                             lo = std::min(lo, g.at(p));
                             hi = std::max(hi, g.at(p));
                         });
                         return lo <= 0.4f && hi >= 0.3f;
                     });
}

TEST(e2e_Aggregates, MaterialFractionOverABox) {
    expectMarksWhere("where bottom { box = [[0, 0, 0], [3, 1, 3]]; material_fraction = [rock, 0.5, 1]; }",
                     [](const DenseGrid& g, glm::ivec3 a) {
                         int rock = 0;
                         forBox(a, {0, 0, 0}, {3, 1, 3}, [&](glm::ivec3 p) { rock += g.materialAt(p) == 1; });
                         return rock >= 5; // 0.5 * 9 = 4.5 -> 5
                     });
}

// Tile skipping reads a `min` test as a bound on every cell of its box: an all-IGN rule that asks
// for solid rock everywhere in its window runs only in tiles holding rock, and gives the same
// grid as running every tile.
TEST(e2e_Aggregates, TileSkippingReadsMinAsACellBound) {
    const Program program = checked(R"(
world { size = [48, 40, 48]; origin = [3, -5, 0]; chunk = 16; seed = 4; }
start { fill { value = 0; } heightfield { base = 10; amplitude = 4; frequency = 0.1; } }
grammar g {
  rule roof {
    size = [2, 2, 2];
    symbol { layer { [IGN, IGN] [IGN, IGN] } layer { [IGN, IGN] [IGN, IGN] } }
    transform { layer { [NOP, NOP] [SET 0.75, NOP] } layer { [NOP, NOP] [NOP, NOP] } }
    where { min = [0.5, 1]; }
  }
}
)");
    VulkanExecutor skipping(test::lavapipe(), compileProgram(program, {}), {});
    const RunResult skipped = skipping.run();
    ASSERT_TRUE(skipped.skip.enabled);
    // Air fills the upper part of the grid, so most tiles cannot hold a window of rock.
    EXPECT_LT(skipped.skip.activeTilePhases * 2, skipped.skip.tilePhases);
    const DenseGrid all = test::runOnLavapipe(program, {.skipInactiveTiles = false});
    EXPECT_EQ(test::countBitDifferences(skipped.grid.toDense(), all), 0u);
    EXPECT_EQ(test::countBitDifferences(interpret(program), all), 0u);
}

} // namespace aggregates_test
} // namespace voxc
