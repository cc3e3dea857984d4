// Which field kernels skip their worley calls where the rest settles the value (FieldKernel.cpp's
// noise skip). That a skipped voxel has the interpreter's bits is tested by the interpreter-vs-
// lavapipe cases (tests/e2e/cases/noise_skip.vox, the lsystem_cave examples and tests/vulkan).
#ifdef VOXC_HAVE_CHECK
#include "voxc/check/Check.h"
#include "voxc/stages/Pipeline.h"

#include <gtest/gtest.h>

namespace voxc::codegen {
namespace noise_skip_test {

// The GLSL of field f = `expression` combined in `mode` (the program's only field kernel).
std::string fieldGlsl(const std::string& expression, const std::string& mode) {
    const std::string text = "world { size = [4, 8, 4]; }\nstart { fill { value = 1; } }\nfield f = " + expression +
                             ";\npipeline { start; " + mode + " f; }\n";
    CheckResult checked = checkSource(SourceFile("noise_skip.vox", text));
    if (!checked.program) throw std::runtime_error(checked.rendered());
    for (const Kernel& kernel : compileProgram(*checked.program).kernels)
        if (kernel.name == "f_" + mode) return kernel.glsl;
    throw std::runtime_error("no kernel f_" + mode);
}

bool has(const std::string& glsl, const std::string& text) { return glsl.find(text) != std::string::npos; }

// A carve's brush: the worley term scales the reach of a cheap distance.
const std::string kBrush = "max(clamp(1 - (1 + 0.3 * worley_f1(wp * 0.2, 3)) * length(p - vec3(2, 4, 2)) * 0.5, 0, 1), "
                           "0.2 - y * 0.1)";

TEST(codegen_NoiseSkip, WorleyCallsRunOnlyWhereTheBoundsDoNotSettleTheValue) {
    const std::string glsl = fieldGlsl(kBrush, "subtract");
    const size_t settled = glsl.find("bool noiseSkipSettled = ");
    const size_t loop = glsl.find("for (int noiseSkip = noiseSkipSettled ? 1 : 0; noiseSkip < 1; ++noiseSkip) {");
    const size_t call = glsl.find("= noiseWorleyF1(");
    ASSERT_NE(settled, std::string::npos);
    ASSERT_NE(loop, std::string::npos);
    EXPECT_LT(settled, loop);
    EXPECT_LT(loop, call); // the call is in the loop
    // A subtract ignores a zero's sign (1 - f), so a settled zero is taken.
    EXPECT_FALSE(has(glsl.substr(settled, loop - settled), "Lo != 0.0"));
    // The worley range bounds the product: lower and upper products of the ends.
    EXPECT_TRUE(has(glsl, "Corner1"));
}

TEST(codegen_NoiseSkip, ModesThatWriteTheFieldSettleOnlyOnNonZeroValues) {
    for (const char* mode : {"set", "union", "intersect"}) {
        SCOPED_TRACE(mode);
        EXPECT_TRUE(has(fieldGlsl(kBrush, mode), "Lo != 0.0;"));
    }
}

TEST(codegen_NoiseSkip, NoSkipThroughOperationsWithoutBoundsOrWithoutWorley) {
    EXPECT_FALSE(has(fieldGlsl("sqrt(worley_f1(wp * 0.2, 3)) - y", "subtract"), "noiseSkip"));
    EXPECT_FALSE(has(fieldGlsl("clamp(1 - simplex3(wp * 0.2, 3) * y, 0, 1)", "subtract"), "noiseSkip"));
    EXPECT_FALSE(has(fieldGlsl("worley_f1(wp * 0.2, 3)", "subtract"), "noiseSkip")); // the root itself
}

} // namespace noise_skip_test
} // namespace voxc::codegen
#endif
