// Non-finite values in the interpreter (docs/language.md, "Non-finite values"): what each field
// mode makes of a field that is NaN or infinite (0 takes its place), a grammar write past the
// float range, and the NaN rules of the builtins that the kernels write out explicitly.
#include "CheckedProgram.h"
#include "voxc/builtins/Functions.h"
#include "voxc/check/Check.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/stages/Pipeline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace voxc {
namespace non_finite_interp_test {

Program checked(const std::string& text) { return test::checkedProgram("test.vox", text); }

// A row of 4 voxels at densities 0, 0.25, 0.75, 1 (a `start` of boxes), then `pipeline`.
const std::string kRow = "world { size = [4, 1, 1]; }\n"
                         "start { box { min = [1, 0, 0]; max = [2, 1, 1]; value = 0.25; }\n"
                         "        box { min = [2, 0, 0]; max = [3, 1, 1]; value = 0.75; }\n"
                         "        box { min = [3, 0, 0]; max = [4, 1, 1]; } }\n"
                         "material sand { id = 3; }\n"
                         "field nan = sqrt(-1 - x);\nfield inf = 1 / (x - x);\nfield ninf = -1 / (x - x);\n";

std::vector<float> row(const std::string& pipeline, std::vector<NonFiniteCount>* counts = nullptr,
                       std::vector<uint8_t>* materials = nullptr) {
    const DenseGrid grid = interpret(checked(kRow + pipeline), InterpOptions{.nonFinite = counts});
    std::vector<float> out;
    for (int x = 0; x < 4; ++x) out.push_back(grid.at({x, 0, 0}));
    if (materials) *materials = grid.materials();
    return out;
}

using Row = std::vector<float>;

TEST(interp_NonFinite, EveryFieldModeCombinesZeroWhereTheFieldIsNotFinite) {
    for (const char* field : {"nan", "inf", "ninf"}) {
        SCOPED_TRACE(field);
        const std::string f(field);
        EXPECT_EQ(row("pipeline { start; set " + f + "; }"), (Row{0, 0, 0, 0}));
        EXPECT_EQ(row("pipeline { start; union " + f + "; }"), (Row{0, 0.25f, 0.75f, 1}));
        EXPECT_EQ(row("pipeline { start; subtract " + f + "; }"), (Row{0, 0.25f, 0.75f, 1})); // min(d, 1 - 0)
        EXPECT_EQ(row("pipeline { start; intersect " + f + "; }"), (Row{0, 0, 0, 0}));        // min(d, 0)
        std::vector<uint8_t> materials;
        row("pipeline { start; set " + f + " material sand; paint " + f + " material sand; }", nullptr, &materials);
        EXPECT_EQ(materials, std::vector<uint8_t>(4, kMaterialNone)); // 0 is never solid: no material
    }
}

TEST(interp_NonFinite, EachStageCountsItsReplacementsAndTheFirstVoxel) {
    std::vector<NonFiniteCount> counts;
    // `half` = sqrt(1.5 - x) is NaN from x = 2 on, so the first replaced voxel is x = 2.
    row("field half = sqrt(1.5 - x);\npipeline { start; union half; set inf; union nan; }", &counts);
    ASSERT_EQ(counts.size(), 4u);
    EXPECT_EQ(counts[0].count, 0u); // start
    EXPECT_EQ(counts[1].count, 2u);
    EXPECT_EQ(counts[1].firstIndex, 2u);
    EXPECT_EQ(counts[2].count, 4u);
    EXPECT_EQ(counts[2].firstIndex, 0u);
    EXPECT_EQ(counts[3].count, 4u);
}

// A field writes 3e38, a grammar adds 3e38 to it: the sum overflows and is stored as 0, counted.
TEST(interp_NonFinite, AGrammarWritePastTheFloatRangeIsStoredAsZero) {
    std::vector<NonFiniteCount> counts;
    const Row result = row("field big = x >= 2 ? 3e38 : 0.5;\n"
                           "grammar grow { rule r { size = [1, 1, 1]; symbol { [GEQ 0.5] } transform { [ADD 3e38] } } }\n"
                           "pipeline { start; set big; grow; }",
                           &counts);
    EXPECT_EQ(result, (Row{3e38f, 3e38f, 0, 0}));
    ASSERT_EQ(counts.size(), 3u);
    EXPECT_EQ(counts[2].count, 2u);
    EXPECT_EQ(counts[2].firstIndex, 2u);
}

Value call(std::string_view name, std::initializer_list<float> args) {
    std::vector<Value> values;
    for (float a : args) values.push_back(Value::makeFloat(a));
    return findFunction(name)->eval(values);
}

TEST(interp_NonFinite, MinMaxClampAndSmoothstepIgnoreANaNOperand) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(call("min", {nan, 1}).v.x, 1.0f);
    EXPECT_EQ(call("min", {1, nan}).v.x, 1.0f);
    EXPECT_EQ(call("max", {nan, -1}).v.x, -1.0f);
    EXPECT_TRUE(std::isnan(call("max", {nan, nan}).v.x));
    EXPECT_EQ(call("clamp", {nan, 0, 1}).v.x, 0.0f); // the clamp(sqrt(8 - y) * 0.3, 0, 1)
    EXPECT_EQ(call("smoothstep", {0, 1, nan}).v.x, 0.0f);
    EXPECT_EQ(call("sdf_union", {nan, 2}).v.x, 2.0f);
    EXPECT_TRUE(std::isnan(call("pow", {-2, 2}).v.x)); // GLSL: undefined for x < 0
    EXPECT_TRUE(std::isnan(call("pow", {0, 0}).v.x));  // GLSL: undefined for x = 0, y <= 0
    EXPECT_EQ(call("pow", {2, 3}).v.x, 8.0f);
    std::vector<Value> point{Value::makeVec3({nan, 0, 0}), Value::makeInt(0)};
    EXPECT_TRUE(std::isnan(findFunction("perlin3")->eval(point).v.x));
}

} // namespace non_finite_interp_test
} // namespace voxc
