// Generated code stays within what SPIR-V allows at every documented limit: the largest sweep the
// checker accepts (Limits::maxSweepRuleCells rule window cells) must compile, so the
// function-local variables of a sweep kernel are measured on two small sweeps and extrapolated
// (glslang copies every call argument into a variable of its own, so they grow with the written
// cells). Counts, never times.
#include "ProgramText.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/StageKind.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <spirv-tools/libspirv.h>

namespace voxc::codegen {
namespace code_size_test {

// SPIR-V 2.17 ("Universal Limits"): at most 524287 variables of the Function storage class.
constexpr double kMaxFunctionVariables = 524287;

// A clamped grammar of [8,8,8] rules whose every cell tests and writes the density (the most
// code per rule).
Program eightCubeProgram(int rules) {
    std::vector<Rule> list;
    for (int r = 0; r < rules; ++r) {
        std::vector<std::string> symbolRows, transformRows;
        for (int z = 0; z < 8; ++z) {
            if (z) {
                symbolRows.push_back("---");
                transformRows.push_back("---");
            }
            for (int y = 0; y < 8; ++y) {
                symbolRows.push_back(r % 2 ? "GEQ 0.5, GEQ 0.5, LT 0.5, GEQ 0.5, GEQ 0.5, LT 0.5, LT 0.5, GEQ 0.5"
                                           : "LT 0.5, GEQ 0.5, GEQ 0.5, LT 0.5, GEQ 0.5, LT 0.5, GEQ 0.5, LT 0.5");
                transformRows.push_back("ADD -0.1, SET 1, ADD 0.2, SET 0, ADD -0.1, SET 1, ADD 0.2, SET 0");
            }
        }
        list.push_back(test::makeRule("r" + std::to_string(r), symbolRows, transformRows));
    }
    Grammar grammar = test::makeGrammar("g", {32, 32, 32}, list);
    grammar.clampMin = 0.0f; // every write is clamped: more code per cell
    grammar.clampMax = 1.0f;
    Program program = test::makeProgram({32, 32, 32}, {grammar});
    stages::describePipeline(program);
    return program;
}

// Function-storage OpVariables of a module (SPIRV-Tools' parser).
size_t functionVariables(const std::vector<uint32_t>& spirv) {
    size_t count = 0;
    spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_1);
    const auto onInstruction = [](void* user, const spv_parsed_instruction_t* instruction) {
        constexpr uint32_t kOpVariable = 59, kStorageClassFunction = 7;
        if (instruction->opcode == kOpVariable && instruction->words[3] == kStorageClassFunction)
            ++*static_cast<size_t*>(user);
        return SPV_SUCCESS;
    };
    EXPECT_EQ(spvBinaryParse(context, &count, spirv.data(), spirv.size(), nullptr, onInstruction, nullptr),
              SPV_SUCCESS);
    spvContextDestroy(context);
    return count;
}

TEST(codegen_CodeSize, TheLargestSweepTheLimitsAllowFitsSpirvsVariableLimit) {
    const Limits limits;
    const auto sweepVariables = [](int rules) {
        const KernelPackage package = compileProgram(eightCubeProgram(rules));
        for (const StagePlan& stage : package.stages)
            if (stage.grammar)
                return double(functionVariables(package.kernels.at(stage.grammar->sweeps.at(0).kernel).spirv));
        ADD_FAILURE() << "no grammar stage";
        return 0.0;
    };
    const double one = sweepVariables(1), three = sweepVariables(3);
    const double perRule = (three - one) / 2, fixed = one - perRule;
    const double cellsAtLimit = double(std::min<int64_t>(int64_t(limits.maxRulesPerSweep) * limits.maxWindowCells,
                                                         limits.maxSweepRuleCells));
    const double atLimit = fixed + perRule / 512 * cellsAtLimit;
    EXPECT_LT(atLimit, kMaxFunctionVariables) << perRule / 512 << " variables per written cell, " << fixed << " fixed";
}

} // namespace code_size_test
} // namespace voxc::codegen
