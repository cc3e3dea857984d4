#pragma once
// Hand-written kernels and hand-built KernelPackages, so the runtime is tested without the
// code generator. Every kernel declares the PushBlock and bindings of KernelPackage.h and
// addresses voxels through the chunk table exactly as ChunkLayout::address does.
#include "voxc/codegen/KernelPackage.h"
#include "voxc/grid/Grid.h"

#include <cstdint>
#include <string>
#include <vector>

namespace voxc::test {

enum class TestKernel {
    Start,  // density = float(world.x + 3*world.y + 7*world.z)
    AddOne, // voxel[anchor] += 1
    Shift,  // voxel[anchor] = voxel[anchor + x] + 1 + 100*iteration + 10000*sweep (window [2,1,1]); order-sensitive
    Seed,   // density = float(seed >> 20), read from gridSize.w
    OversizedPush, // reads a push-constant field past the 112-byte range: invalid, for validation tests
};

// GLSL compute source -> SPIR-V (glslang, Vulkan 1.0 target); throws std::runtime_error with the log.
std::vector<uint32_t> compileGlsl(const std::string& source);
// The kernel, compiled once per process.
Kernel makeKernel(TestKernel kind);

struct TestSweep {
    TestKernel kernel;
    glm::ivec3 window;
};

struct TestGrammar {
    glm::ivec3 stride{1};
    glm::ivec3 boundsMin{0}, boundsMax{0}; // boundsMax 0: the whole grid
    int32_t iterations = 1;
    std::vector<TestSweep> sweeps; // one rule each; the plan orders them as voxc::orderSweeps does
};

// kernels: one per TestKernel kind used, in first-use order; stages: optional start, then grammars.
KernelPackage makePackage(const World& world, bool withStart, const std::vector<TestGrammar>& grammars,
                          TestKernel startKernel = TestKernel::Start);

// What the package computes, evaluated on the CPU by walking its plan.
DenseGrid referenceResult(const KernelPackage& package);

World makeWorld(glm::ivec3 size, glm::ivec3 origin, int32_t chunkSize, uint32_t seed = 0);

} // namespace voxc::test
