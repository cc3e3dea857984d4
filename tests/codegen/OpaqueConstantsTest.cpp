// Which constants of a field expression the kernel hides from the shader compilers
// (opaque_constants.glsl; docs/fuzzing.md, "Fixed: constant zero operands on lavapipe"): zeros,
// arguments of library records but pow's, and the values of calls on constants alone. The
// interpreter-vs-lavapipe agreement itself is tested by tests/fuzz/regressions/diff/.
#ifdef VOXC_HAVE_CHECK
#include "voxc/check/Check.h"
#include "voxc/stages/Pipeline.h"

#include <gtest/gtest.h>

namespace voxc::codegen {
namespace opaque_constants_test {

// The GLSL of field f = `expression` (the only field kernel of the program).
std::string fieldGlsl(const std::string& expression) {
    const std::string text = "world { size = [4, 4, 4]; }\nfield f = " + expression + ";\npipeline { start; set f; }\n";
    CheckResult checked = checkSource(SourceFile("opaque.vox", text));
    if (!checked.program) throw std::runtime_error(checked.rendered());
    for (const Kernel& kernel : compileProgram(*checked.program).kernels)
        if (kernel.name == "f_set") return kernel.glsl;
    throw std::runtime_error("no kernel f_set");
}

bool has(const std::string& glsl, const std::string& text) { return glsl.find(text) != std::string::npos; }

TEST(codegen_OpaqueConstants, ZerosOfEitherSignAreOpaque) {
    EXPECT_TRUE(has(fieldGlsl("0 - x"), "(opaqueConstant(0.0) - n0)"));
    EXPECT_TRUE(has(fieldGlsl("x * -0"), "(n0 * opaqueConstant(-0.0))"));
    EXPECT_TRUE(has(fieldGlsl("(vec3(x, x, x) * vec3(1, 0, 2)).y"), "opaqueConstant(vec3(1.0, 0.0, 2.0))"));
    EXPECT_TRUE(has(fieldGlsl("x * 3 + 1"), "(n0 * 3.0)")); // other operands of operators stay literal
}

TEST(codegen_OpaqueConstants, LibraryArgumentsAreOpaqueButPows) {
    EXPECT_TRUE(has(fieldGlsl("mix(x, 2, 1)"), "mathMix(n0, opaqueConstant(2.0), opaqueConstant(1.0))"));
    EXPECT_TRUE(has(fieldGlsl("pow(x, 2)"), "mathPow(n0, 2.0)"));
}

// Their operands are variables, which the driver folds in float (glslang would fold literals in
// double), and their value is opaque, so nothing after them is folded.
TEST(codegen_OpaqueConstants, CallsOnConstantsAloneAreFoldedInFloatAndHideTheirValue) {
    const std::string glsl = fieldGlsl("x * (sqrt(4) - 2) + pow(2, 1.5) + div(mul(10.64, 17.23), -3.612)");
    EXPECT_TRUE(has(glsl, "precise float n1 = 4.0; // constant, for the driver to fold in float"));
    EXPECT_TRUE(has(glsl, "= opaqueConstant(sqrt(n1));"));
    EXPECT_TRUE(has(glsl, "= opaqueConstant(mathPow(n"));
    EXPECT_TRUE(has(glsl, "= 183.327194; // constant, for the driver to fold in float"));
}

} // namespace opaque_constants_test
} // namespace voxc::codegen
#endif
