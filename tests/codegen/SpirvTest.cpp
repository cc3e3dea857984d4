#include "ProgramText.h"
#include "SamplePrograms.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/StageKind.h"
#include "voxc/codegen/Spirv.h"
#include "voxc/core/Errors.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace voxc::codegen {
namespace spirv_test {

TEST(codegen_Spirv, EveryKernelOfTheSampleIsValid) {
    const KernelPackage package = compileProgram(test::sampleProgram());
    // start, overhang x2, smooth x2, an active-tiles kernel per sweep with live rules, tile_ranges
    ASSERT_EQ(package.kernels.size(), 9u);
    for (const Kernel& kernel : package.kernels) {
        ASSERT_GT(kernel.spirv.size(), 5u) << kernel.name;
        EXPECT_EQ(kernel.spirv[0], 0x07230203u) << kernel.name; // SPIR-V magic
        EXPECT_EQ(spirvValidationErrors(kernel.spirv), std::nullopt) << kernel.name;
    }
}

TEST(codegen_Spirv, TemplatesAreFullyInstantiated) {
    for (const Kernel& kernel : compileProgram(test::sampleProgram()).kernels) {
        EXPECT_EQ(kernel.glsl.rfind("#version 450\n", 0), 0u) << kernel.name;
        EXPECT_EQ(kernel.glsl.find("#include"), std::string::npos) << kernel.name;
        EXPECT_EQ(kernel.glsl.find("// <<"), std::string::npos) << kernel.name; // a section marker left
        EXPECT_NE(kernel.glsl.find("int voxelAddress(ivec3 local)"), std::string::npos) << kernel.name;
    }
}

TEST(codegen_Spirv, CompileFailureIsAnInternalErrorWithNumberedSource) {
    const std::string broken = "#version 450\nlayout(local_size_x = 8) in;\nvoid main() { undeclared = 1; }\n";
    try {
        compileComputeShader("broken", broken);
        FAIL() << "expected an InternalError";
    } catch (const InternalError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("generated kernel 'broken' does not compile"), std::string::npos) << what;
        EXPECT_NE(what.find("undeclared"), std::string::npos) << what;
        EXPECT_NE(what.find("    3 | void main() { undeclared = 1; }"), std::string::npos) << what;
    }
}

TEST(codegen_Spirv, ValidatorRejectsBrokenModules) {
    std::vector<uint32_t> spirv = compileProgram(test::sampleProgram()).kernels.at(1).spirv;
    spirv.resize(spirv.size() / 2);
    EXPECT_NE(spirvValidationErrors(spirv), std::nullopt);
}

TEST(codegen_Spirv, CellsWithMoreThan32PredicatesUseSeveralMasks) {
    std::vector<Rule> rules;
    for (int k = 0; k < 40; ++k)
        rules.push_back(test::makeRule(fmt::format("r{}", k), {fmt::format("EQ {}", k)}, {"SET 1"}));
    Program program = test::makeProgram({8, 8, 8}, {test::makeGrammar("many", {8, 8, 8}, rules)});
    stages::describePipeline(program);
    const KernelPackage package = compileProgram(program);
    const Kernel& kernel = package.kernels.at(1);
    EXPECT_NE(kernel.glsl.find("uint pass0_1 = ((cell0 == 32.0) ? 0x1u : 0u)"), std::string::npos) << kernel.glsl;
    EXPECT_NE(kernel.glsl.find("matched39 = matched39 && (pass0_1 & 0x80u) == 0x80u;"), std::string::npos) << kernel.glsl;
    EXPECT_EQ(spirvValidationErrors(kernel.spirv), std::nullopt);
}

} // namespace spirv_test
} // namespace voxc::codegen
