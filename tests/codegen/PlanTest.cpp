#include "SamplePrograms.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/program/Semantics.h"
#include "voxc/stages/StageKind.h"

#include <gtest/gtest.h>

namespace voxc::codegen {
namespace plan_test {

std::vector<std::string> kernelNames(const KernelPackage& package) {
    std::vector<std::string> names;
    for (const Kernel& k : package.kernels)
        names.push_back(k.name);
    return names;
}

TEST(codegen_Plan, OneKernelPerSweepAndPhasesFromSemantics) {
    const Program program = test::sampleProgram();
    const KernelPackage package = compileProgram(program);
    EXPECT_EQ(kernelNames(package),
              (std::vector<std::string>{"start", "overhang_sweep0", "overhang_sweep1", "smooth_sweep0", "smooth_sweep1",
                                        "overhang_sweep0_active_tiles", "overhang_sweep1_active_tiles",
                                        "smooth_sweep0_active_tiles", "tile_ranges"}));
    EXPECT_EQ(package.tileRangesKernel, 8u);
    ASSERT_EQ(package.stages.size(), 3u);
    EXPECT_EQ(package.stages[0].kind, "start");
    EXPECT_EQ(package.kernels[package.stages[0].gridKernel].name, "start");
    for (size_t g = 0; g < 2; ++g) {
        const StagePlan& stage = package.stages[g + 1];
        const Grammar& grammar = program.grammars[g];
        ASSERT_EQ(stage.kind, "grammar");
        ASSERT_TRUE(stage.grammar);
        EXPECT_EQ(stage.grammar->name, grammar.name);
        EXPECT_EQ(stage.grammar->iterations, uint32_t(grammar.iterations));
        const std::vector<Sweep> sweeps = orderSweeps(grammar);
        ASSERT_EQ(stage.grammar->sweeps.size(), sweeps.size());
        for (size_t s = 0; s < sweeps.size(); ++s) {
            const SweepPlan& plan = stage.grammar->sweeps[s];
            EXPECT_EQ(package.kernels.at(plan.kernel).name, grammar.name + "_sweep" + std::to_string(s));
            // smooth's second sweep has no live rule, so nothing to classify tiles for.
            if (g == 1 && s == 1) {
                EXPECT_EQ(plan.activeTilesKernel, kNoKernel);
            } else {
                EXPECT_EQ(package.kernels.at(plan.activeTilesKernel).name,
                          grammar.name + "_sweep" + std::to_string(s) + "_active_tiles");
            }
            EXPECT_EQ(plan.window, sweeps[s].window);
            EXPECT_EQ(plan.phaseCount, sweeps[s].phaseCount);
            ASSERT_EQ(plan.phaseStart.size(), size_t(sweeps[s].phases()));
            ASSERT_EQ(plan.phaseStep.size(), plan.phaseStart.size());
            ASSERT_EQ(plan.phaseCount3.size(), plan.phaseStart.size());
            for (int p = 0; p < sweeps[s].phases(); ++p) {
                const PhaseAnchors anchors = phaseAnchors(grammar, sweeps[s], p);
                EXPECT_EQ(plan.phaseStart[p], anchors.start);
                EXPECT_EQ(plan.phaseStep[p], anchors.step);
                EXPECT_EQ(plan.phaseCount3[p], anchors.count);
            }
        }
    }
    EXPECT_EQ(package.kernels[1].origin, "sample.vox:8:1 grammar overhang, window [3,3,1]");
    EXPECT_EQ(package.world.origin, program.world.origin);
}

TEST(codegen_Plan, GrammarRunTwiceSharesItsKernels) {
    Program program = test::sampleProgram();
    program.pipeline.push_back(stages::makeStage(program, Stage::Kind::Grammar, 0));
    const KernelPackage package = compileProgram(program);
    EXPECT_EQ(package.kernels.size(), 9u);
    ASSERT_EQ(package.stages.size(), 4u);
    EXPECT_EQ(package.stages[3].grammar->name, "overhang");
    EXPECT_EQ(package.stages[3].grammar->sweeps.at(0).kernel, package.stages[1].grammar->sweeps.at(0).kernel);
    EXPECT_EQ(package.stages[3].grammar->sweeps.at(0).activeTilesKernel,
              package.stages[1].grammar->sweeps.at(0).activeTilesKernel);
}

TEST(codegen_Plan, SweepKernelsCarryTheirRulesAndWindow) {
    const KernelPackage package = compileProgram(test::sampleProgram());
    const std::string& glsl = package.kernels.at(1).glsl;
    EXPECT_NE(glsl.find("grammar overhang"), std::string::npos);
    EXPECT_NE(glsl.find("erode (sample.vox:12:3)"), std::string::npos);
    EXPECT_NE(glsl.find("never (sample.vox:28:3): removed"), std::string::npos);
    EXPECT_NE(glsl.find("Window [3, 3, 1]"), std::string::npos);
    // The removed rule never reaches the rule table.
    EXPECT_NE(glsl.find("bool matched1 = true;"), std::string::npos);
    EXPECT_EQ(glsl.find("bool matched2"), std::string::npos);
    // The all-rules-removed sweep gets the no-op kernel.
    EXPECT_NE(package.kernels.at(4).glsl.find("Every rule of this sweep can never match"), std::string::npos);
}

} // namespace plan_test
} // namespace voxc::codegen
