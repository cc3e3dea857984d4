#include "TestKernels.h"

#include "voxc/program/Semantics.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <map>
#include <mutex>
#include <stdexcept>

namespace voxc::test {

namespace {

// `oversized` adds a field past the end of the PushBlock.
std::string prelude(bool oversized) {
    const std::string extra = oversized ? "    ivec4 beyondPushBlock;\n" : "";
    return R"(#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(push_constant, std430) uniform PushBlock {
    ivec4 gridOrigin;  ivec4 gridSize;  ivec4 chunkBase;  ivec4 chunkCount;
    ivec4 anchorStart; ivec4 anchorStep; ivec4 anchorCount;
)" + extra + R"(} pc;
layout(std430, set = 0, binding = 0) buffer Voxels { float voxels[]; };
layout(std430, set = 0, binding = 1) readonly buffer ChunkTable { int chunkSlot[]; };

uint voxelAddress(ivec3 local) {
    int C = pc.gridOrigin.w;
    ivec3 world = pc.gridOrigin.xyz + local;
    ivec3 entry = (world >> findLSB(C)) - pc.chunkBase.xyz;
    ivec3 inside = world & (C - 1);
    int slot = chunkSlot[entry.x + pc.chunkCount.x * (entry.y + pc.chunkCount.y * entry.z)];
    return uint(slot) * uint(C * C * C) + uint(inside.x + C * (inside.y + C * inside.z));
}

bool anchor(out ivec3 local) {
    ivec3 i = ivec3(gl_GlobalInvocationID);
    local = pc.anchorStart.xyz + i * pc.anchorStep.xyz;
    return all(lessThan(i, pc.anchorCount.xyz));
}
)";
}

const char* body(TestKernel kind) {
    switch (kind) {
    case TestKernel::Start:
        return "void main() { ivec3 p; if (!anchor(p)) return; ivec3 w = pc.gridOrigin.xyz + p;\n"
               "  voxels[voxelAddress(p)] = float(w.x + 3 * w.y + 7 * w.z); }\n";
    case TestKernel::AddOne:
        return "void main() { ivec3 p; if (!anchor(p)) return; voxels[voxelAddress(p)] += 1.0; }\n";
    case TestKernel::Shift:
        return "void main() { ivec3 p; if (!anchor(p)) return;\n"
               "  voxels[voxelAddress(p)] = voxels[voxelAddress(p + ivec3(1, 0, 0))] + 1.0\n"
               "      + float(100 * pc.chunkBase.w + 10000 * pc.chunkCount.w); }\n";
    case TestKernel::Seed:
        return "void main() { ivec3 p; if (!anchor(p)) return;\n"
               "  voxels[voxelAddress(p)] = float(uint(pc.gridSize.w) >> 20); }\n";
    case TestKernel::OversizedPush:
        return "void main() { ivec3 p; if (!anchor(p)) return; voxels[voxelAddress(p)] = float(pc.beyondPushBlock.x); }\n";
    }
    return "";
}

const char* kernelName(TestKernel kind) {
    switch (kind) {
    case TestKernel::Start: return "start";
    case TestKernel::AddOne: return "add_one";
    case TestKernel::Shift: return "shift";
    case TestKernel::Seed: return "seed";
    case TestKernel::OversizedPush: return "oversized_push";
    }
    return "";
}

TestKernel kindOf(const Kernel& kernel) {
    for (TestKernel k : {TestKernel::Start, TestKernel::AddOne, TestKernel::Shift, TestKernel::Seed,
                         TestKernel::OversizedPush})
        if (kernel.name == kernelName(k)) return k;
    throw std::runtime_error("not a test kernel: " + kernel.name);
}

} // namespace

std::vector<uint32_t> compileGlsl(const std::string& source) {
    static std::once_flag init;
    std::call_once(init, [] { glslang::InitializeProcess(); });
    glslang::TShader shader(EShLangCompute);
    const char* text = source.c_str();
    shader.setStrings(&text, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    const EShMessages messages = EShMessages(EShMsgSpvRules | EShMsgVulkanRules);
    if (!shader.parse(GetDefaultResources(), 450, false, messages))
        throw std::runtime_error(std::string("GLSL: ") + shader.getInfoLog() + "\n" + source);
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages)) throw std::runtime_error(std::string("link: ") + program.getInfoLog());
    std::vector<uint32_t> spirv;
    glslang::GlslangToSpv(*program.getIntermediate(EShLangCompute), spirv);
    return spirv;
}

Kernel makeKernel(TestKernel kind) {
    static std::mutex mutex;
    static std::map<TestKernel, Kernel> cache;
    std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(kind);
    if (it != cache.end()) return it->second;
    Kernel kernel;
    kernel.name = kernelName(kind);
    kernel.origin = "tests/vulkan/TestKernels.cpp";
    kernel.glsl = prelude(kind == TestKernel::OversizedPush) + body(kind);
    kernel.spirv = compileGlsl(kernel.glsl);
    return cache.emplace(kind, kernel).first->second;
}

World makeWorld(glm::ivec3 size, glm::ivec3 origin, int32_t chunkSize, uint32_t seed) {
    World world;
    world.size = size;
    world.origin = origin;
    world.chunkSize = chunkSize;
    world.seed = seed;
    return world;
}

KernelPackage makePackage(const World& world, bool withStart, const std::vector<TestGrammar>& grammars,
                          TestKernel startKernel) {
    KernelPackage package;
    package.world = world;
    std::map<TestKernel, uint32_t> index;
    const auto kernelIndex = [&](TestKernel kind) {
        auto [it, inserted] = index.emplace(kind, uint32_t(package.kernels.size()));
        if (inserted) package.kernels.push_back(makeKernel(kind));
        return it->second;
    };
    if (withStart) {
        StagePlan stage;
        stage.kind = "start";
        stage.gridKernel = kernelIndex(startKernel);
        package.stages.push_back(stage);
    }
    for (size_t g = 0; g < grammars.size(); ++g) {
        const TestGrammar& spec = grammars[g];
        Grammar grammar;
        grammar.stride = spec.stride;
        grammar.boundsMin = spec.boundsMin;
        grammar.boundsMax = spec.boundsMax == glm::ivec3(0) ? world.size : spec.boundsMax;
        grammar.iterations = spec.iterations;
        for (const TestSweep& sweep : spec.sweeps) {
            Rule rule;
            rule.name = kernelName(sweep.kernel);
            rule.size = sweep.window;
            grammar.rules.push_back(rule);
        }
        StagePlan stage;
        stage.kind = "grammar";
        stage.grammar.emplace();
        stage.grammar->name = "g" + std::to_string(g);
        stage.grammar->iterations = uint32_t(spec.iterations);
        for (const Sweep& sweep : orderSweeps(grammar)) {
            SweepPlan plan;
            plan.kernel = kernelIndex(spec.sweeps[sweep.rules.front()].kernel);
            plan.window = sweep.window;
            plan.phaseCount = sweep.phaseCount;
            fillPhaseAnchors(plan, grammar, sweep);
            stage.grammar->sweeps.push_back(plan);
        }
        package.stages.push_back(stage);
    }
    return package;
}

DenseGrid referenceResult(const KernelPackage& package) {
    const World& world = package.world;
    DenseGrid grid(world.size, 0.0f);
    // Sequential application equals the GPU's parallel one: windows of one phase never overlap.
    const auto apply = [&](TestKernel kind, glm::ivec3 p, int iteration, int sweep) {
        const glm::ivec3 w = world.origin + p;
        switch (kind) {
        case TestKernel::Start: grid.at(p) = float(w.x + 3 * w.y + 7 * w.z); break;
        case TestKernel::AddOne: grid.at(p) += 1.0f; break;
        case TestKernel::Shift:
            grid.at(p) = grid.at(p + glm::ivec3(1, 0, 0)) + 1.0f + float(100 * iteration + 10000 * sweep);
            break;
        case TestKernel::Seed: grid.at(p) = float(world.seed >> 20); break;
        case TestKernel::OversizedPush: throw std::runtime_error("oversized_push has no defined result");
        }
    };
    const auto applyPhase = [&](TestKernel kind, glm::ivec3 start, glm::ivec3 step, glm::ivec3 count, int iteration,
                                int sweep) {
        for (int z = 0; z < count.z; ++z)
            for (int y = 0; y < count.y; ++y)
                for (int x = 0; x < count.x; ++x) apply(kind, start + glm::ivec3(x, y, z) * step, iteration, sweep);
    };
    for (const StagePlan& stage : package.stages) {
        if (stage.gridKernel != kNoKernel)
            applyPhase(kindOf(package.kernels[stage.gridKernel]), glm::ivec3(0), glm::ivec3(1), world.size, 0, 0);
        if (!stage.grammar) continue;
        for (uint32_t it = 0; it < stage.grammar->iterations; ++it)
            for (size_t s = 0; s < stage.grammar->sweeps.size(); ++s) {
                const SweepPlan& sweep = stage.grammar->sweeps[s];
                for (size_t p = 0; p < sweep.phaseStart.size(); ++p)
                    applyPhase(kindOf(package.kernels[sweep.kernel]), sweep.phaseStart[p], sweep.phaseStep[p],
                               sweep.phaseCount3[p], int(it), int(s));
            }
    }
    return grid;
}

} // namespace voxc::test
