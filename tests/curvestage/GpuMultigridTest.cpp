// The curves' linear solves on lavapipe (voxc/vulkan/GpuMultigrid.h) against the host's
// solveLaplace, the reference: every unknown bit-identical, the same residual after FMG and after
// every V-cycle, on boxes with 1 to 7 levels, odd and flat sizes, 2 and 3 components; then a
// whole curves block (check with the Vulkan solver) gives the host's table bit for bit, and its
// run on lavapipe the interpreter's grid at chunk sizes 8/16/32 and an odd origin; the SPIR-V of
// the passes is valid and the validation layer stays quiet.
#include "../curves/Scenes.h"
#include "GridCompare.h"
#include "Lavapipe.h"
#include "Programs.h"
#include "voxc/check/Check.h"
#include "voxc/codegen/Spirv.h"
#include "voxc/generators/curves/Scene.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Solve.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/GpuMultigrid.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <bit>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace voxc {
namespace {

// lavapipe with the validation layer: every test here asks it to stay quiet.
using test::expectNoValidationMessages;
VulkanContext& validated() { return test::validatedLavapipe(); }

size_t bitDifferences(const curves::Field3& a, const curves::Field3& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.values.size(); ++i)
        n += std::bit_cast<uint32_t>(a.values[i]) != std::bit_cast<uint32_t>(b.values[i]);
    return n;
}

// Both solves of the curves' constraints on `box` (the cliff scene shifted so it meets the box).
void expectSolvesMatch(const curves::Box& box, glm::dvec3 shift) {
    std::vector<curves::FeatureCurve> scene = curves::test::cliffScene();
    for (curves::FeatureCurve& c : scene)
        for (glm::dvec3& p : c.points) p += shift;
    const curves::Limits limits;
    const curves::Constraints cs = curves::voxelize(scene, box, curves::SeedValue::PlaneDistance, limits);
    std::vector<uint8_t> fixedN(cs.flags.size()), fixedR(cs.flags.size());
    for (size_t i = 0; i < cs.flags.size(); ++i) {
        fixedN[i] = (cs.flags[i] & curves::kInNormals) ? 1 : 0;
        fixedR[i] = (cs.flags[i] & curves::kInParams) ? 1 : 0;
    }
    const curves::LinearSolver device = vulkanLinearSolver(validated());
    {
        curves::Field3 hx = cs.normalX, hy = cs.normalY, hz = cs.normalZ;
        curves::Field3 dx = hx, dy = hy, dz = hz;
        const curves::SolveReport host = curves::solveLaplace("normals", fixedN, {&hx, &hy, &hz}, 1e-5f, limits);
        const curves::SolveReport gpu = device("normals", fixedN, {&dx, &dy, &dz}, 1e-5f, limits);
        EXPECT_EQ(gpu.levels, host.levels);
        EXPECT_EQ(gpu.residuals, host.residuals);
        EXPECT_EQ(bitDifferences(hx, dx) + bitDifferences(hy, dy) + bitDifferences(hz, dz), 0u);
    }
    {
        curves::Field3 ha = cs.amplitude, hb = cs.roughness, da = ha, db = hb;
        const curves::SolveReport host = curves::solveLaplace("parameters", fixedR, {&ha, &hb}, 6e-5f, limits);
        const curves::SolveReport gpu = device("parameters", fixedR, {&da, &db}, 6e-5f, limits);
        EXPECT_EQ(gpu.residuals, host.residuals);
        EXPECT_EQ(bitDifferences(ha, da) + bitDifferences(hb, db), 0u);
    }
}

TEST(vulkan_GpuMultigrid, MatchesTheHostBitForBit) {
    const struct {
        glm::ivec3 min, size;
    } boxes[] = {{{0, 0, 0}, {64, 32, 64}}, {{3, 5, 2}, {37, 19, 45}}, {{0, 8, 0}, {64, 6, 64}}, {{10, 10, 20}, {7, 5, 6}},
                 // Over 2^18 cells with an odd slice count: the host smooths its finest level on two
                 // threads, with unequal halves.
                 {{0, 0, 0}, {66, 64, 63}}};
    for (const auto& b : boxes) {
        SCOPED_TRACE(fmt::format("box {}x{}x{} at {},{},{}", b.size.x, b.size.y, b.size.z, b.min.x, b.min.y, b.min.z));
        expectSolvesMatch(curves::Box{b.min, b.size}, glm::dvec3(0.0));
    }
    expectNoValidationMessages();
}

// Past the cycle cap the device solve fails as the host's does, with the same numbers.
TEST(vulkan_GpuMultigrid, CycleCapIsTheHostsConvergenceError) {
    const curves::Box box{glm::ivec3(0), glm::ivec3(32, 16, 32)};
    curves::Limits limits;
    limits.maxCycles = 1;
    const curves::Constraints cs =
        curves::voxelize(curves::test::cliffScene(), box, curves::SeedValue::PlaneDistance, limits);
    std::vector<uint8_t> fixed(cs.flags.size());
    for (size_t i = 0; i < fixed.size(); ++i) fixed[i] = (cs.flags[i] & curves::kInParams) ? 1 : 0;
    const auto failure = [&](const curves::LinearSolver& solver) {
        curves::Field3 a = cs.amplitude;
        try {
            solver("parameters", fixed, {&a}, 1e-12f, limits);
        } catch (const curves::ConvergenceError& e) {
            return std::pair(e.cycles, e.residual);
        }
        ADD_FAILURE() << "no ConvergenceError";
        return std::pair(0, 0.0);
    };
    const auto host = failure(curves::solveLaplace);
    EXPECT_EQ(host.first, 1);
    EXPECT_EQ(failure(vulkanLinearSolver(validated())), host);
    expectNoValidationMessages();
}

// The level rule and the program's shape: every step's workgroups cover its level.
TEST(vulkan_GpuMultigrid, ProgramCoversEveryLevel) {
    const std::vector<curves::MultigridLevel> levels = curves::multigridLevels({128, 6, 96});
    ASSERT_EQ(levels.size(), 6u); // 128x6x96, 64x3x48, ..., 4x1x3
    EXPECT_EQ(levels.back().size, glm::ivec3(4, 1, 3));
    const SolveProgram p = multigridProgram(levels, 3, 1e-5f, 30);
    EXPECT_EQ(p.kernels.size(), 4u);
    for (const Kernel& k : p.kernels) EXPECT_FALSE(codegen::spirvValidationErrors(k.spirv).has_value()) << k.name;
    // FMG: 5 restrictions down, 50 sweeps x 2 colours, then per finer level a prolongation and a V-cycle.
    EXPECT_EQ(p.prologue.front().kernel, 1u);
    // A V-cycle from the finest: per non-coarsest level 6 + 1 + 1 + 6 steps, then 100 on the coarsest.
    EXPECT_EQ(p.cycle.size(), 5u * 14u + 100u);
    EXPECT_EQ(p.measure.size(), 1u);
}

// The host's and the device's solve of a checked program: stages::solveBlocks with the Vulkan
// solver or without.
std::pair<Program, Program> hostAndDeviceSolved(const SourceFile& source) {
    const CheckResult checked = checkSource(source, CheckOptions{});
    if (!checked.program) throw std::runtime_error(checked.rendered());
    std::pair<Program, Program> solved{*checked.program, *checked.program};
    stages::solveBlocks(solved.first);
    stages::solveBlocks(solved.second, {vulkanLinearSolver(validated())});
    return solved;
}

// A curves block solved with the Vulkan solver gives the table the host solve gives.
TEST(vulkan_GpuMultigrid, CurvesExampleTableMatchesTheHost) {
    std::ifstream in(std::string(VOXC_SOURCE_DIR) + "/examples/curves_cliff.vox");
    std::stringstream text;
    text << in.rdbuf();
    const auto [host, device] = hostAndDeviceSolved(SourceFile("curves_cliff.vox", text.str()));
    ASSERT_EQ(host.curves.size(), device.curves.size());
    for (size_t i = 0; i < host.curves.size(); ++i) {
        const SolveTable& a = host.curves[i].solved();
        const SolveTable& b = device.curves[i].solved();
        ASSERT_EQ(a.density.size(), b.density.size());
        size_t differences = 0;
        for (size_t c = 0; c < a.density.size(); ++c)
            differences += std::bit_cast<uint32_t>(a.density[c]) != std::bit_cast<uint32_t>(b.density[c]);
        EXPECT_EQ(differences, 0u);
        EXPECT_EQ(a.material, b.material);
        ASSERT_EQ(a.solves.size(), b.solves.size());
        for (size_t s = 0; s < a.solves.size(); ++s) EXPECT_EQ(a.solves[s].residuals, b.solves[s].residuals);
    }
    expectNoValidationMessages();
}

// The whole pipeline with the multigrid solved on the device: lavapipe's run equals the
// interpreter's run of the host-solved program, at chunk sizes 8, 16, 32 and an odd negative origin.
TEST(vulkan_GpuMultigrid, DeviceSolvedRunMatchesTheInterpreter) {
    for (const char* world : {"", "origin = [-13, -6, 5];"}) {
        SCOPED_TRACE(world);
        const auto [host, device] = hostAndDeviceSolved(SourceFile("ridge.vox", test::ridgeProgram("union", world)));
        test::expectLavapipeMatchesAtEveryChunkSize(device, interpret(host));
    }
    expectNoValidationMessages();
}

} // namespace
} // namespace voxc
